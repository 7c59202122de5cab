// FrameVertices: an owning one keeps its positions through copies and moves (deep copies that
// point at their own storage); a view of caller memory stays a view, points at that memory
// and never copies it.

#include "collidescope/scene.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace collidescope {
namespace {

const std::vector<Vec3> k_points = {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-4, 5.5, 6)};

TEST(FrameVertices, OwningCopiesAreDeepAndMovesKeepTheBuffer) {
    FrameVertices owned(k_points);
    EXPECT_TRUE(owned.owns());
    ASSERT_EQ(owned.size(), 3u);
    EXPECT_EQ(owned[1], Vec3(1, 2, 3));

    const FrameVertices copy = owned;
    EXPECT_TRUE(copy.owns());
    EXPECT_NE(copy.data(), owned.data()) << "a copy of owned positions has storage of its own";
    EXPECT_TRUE(copy == owned);

    const Vec3* buffer = owned.data();
    FrameVertices moved = std::move(owned);
    EXPECT_EQ(moved.data(), buffer) << "a move hands the buffer over";
    EXPECT_TRUE(moved.owns());
    EXPECT_TRUE(moved == FrameVertices(k_points));

    FrameVertices assigned;
    assigned = copy;
    EXPECT_NE(assigned.data(), copy.data());
    EXPECT_EQ(assigned.to_vector(), k_points);
}

TEST(FrameVertices, ViewsPointAtTheCallersMemory) {
    std::vector<Vec3> caller = k_points;
    const FrameVertices view = FrameVertices::view(caller);
    EXPECT_FALSE(view.owns());
    EXPECT_EQ(view.data(), caller.data());
    EXPECT_EQ(view.size(), caller.size());

    const FrameVertices copy = view;
    EXPECT_FALSE(copy.owns());
    EXPECT_EQ(copy.data(), caller.data()) << "copying a view copies the view, not the positions";

    caller[2] = Vec3(7, 8, 9);  // a view sees the caller's memory as it is
    EXPECT_EQ(view[2], Vec3(7, 8, 9));

    const std::vector<Vec3> kept = view.to_vector();  // what outlives the caller's memory
    caller[2] = Vec3(0, 0, 0);
    EXPECT_EQ(kept[2], Vec3(7, 8, 9));
}

TEST(FrameVertices, ReadAsASpanLikeTheVectorItReplaced) {
    const FrameVertices owned{Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const std::span<const Vec3> span = owned;
    EXPECT_EQ(span.data(), owned.data());
    EXPECT_EQ(span.size(), 2u);
    double sum = 0;
    for (const Vec3& v : owned) sum += v.sum();
    EXPECT_EQ(sum, 2.0);
    EXPECT_TRUE(FrameVertices().empty());
    EXPECT_TRUE(FrameVertices() == FrameVertices::view({}));
}

// A frame's objects keep their views through the Frame's own copies (tests and sources copy
// frames): the positions are still the caller's, and an ObjectFrame reads its corners there.
TEST(FrameVertices, ObjectFramesReadCornersThroughAView) {
    auto topology = std::make_shared<Topology>();
    topology->triangles = {{0, 1, 2}};
    topology->vertex_count = 3;
    std::vector<Vec3> caller = k_points;
    Frame frame;
    frame.objects.push_back({topology, FrameVertices::view(caller)});
    const Frame copy = frame;
    EXPECT_EQ(copy.objects[0].vertices.data(), caller.data());
    EXPECT_EQ(copy.objects[0].corners(0)[2], Vec3(-4, 5.5, 6));
}

}  // namespace
}  // namespace collidescope
