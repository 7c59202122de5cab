// The object level: sweep and prune against every object pair, on random boxes snapped to a
// coarse grid (so boxes often touch exactly, share faces or are flat).

#include "stages/object_level.hpp"

#include "support/scene_builders.hpp"

#include <gtest/gtest.h>

#include <random>

namespace collidescope {
namespace {

Eigen::AlignedBox3d random_box(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> coordinate(0, 8);
    std::uniform_int_distribution<int> extent(0, 3);  // 0: a flat box
    Vec3 lo(coordinate(rng), coordinate(rng), coordinate(rng));
    Vec3 hi = lo + Vec3(extent(rng), extent(rng), extent(rng));
    return Eigen::AlignedBox3d(lo, hi);
}

// Every pair a < b with closed boxes overlapping, written out per axis.
std::vector<ObjectPair> all_overlapping_pairs(const std::vector<Eigen::AlignedBox3d>& boxes) {
    std::vector<ObjectPair> pairs;
    for (std::uint32_t a = 0; a < boxes.size(); ++a) {
        for (std::uint32_t b = a + 1; b < boxes.size(); ++b) {
            bool overlap = true;
            for (int axis = 0; axis < 3; ++axis) {
                overlap = overlap && boxes[a].min()[axis] <= boxes[b].max()[axis] &&
                          boxes[b].min()[axis] <= boxes[a].max()[axis];
            }
            if (overlap) pairs.push_back({a, b});
        }
    }
    return pairs;
}

TEST(SweepAndPrune, MatchesAllPairsOnRandomBoxes) {
    std::size_t found = 0;
    std::size_t possible = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937_64 rng(seed);
        std::vector<Eigen::AlignedBox3d> boxes(std::uniform_int_distribution<std::size_t>(0, 30)(rng));
        for (Eigen::AlignedBox3d& box : boxes) box = random_box(rng);
        const std::vector<ObjectPair> expected = all_overlapping_pairs(boxes);
        ASSERT_EQ(find_object_pairs(boxes, false), expected);
        found += expected.size();
        possible += boxes.size() * (boxes.size() - (boxes.empty() ? 0 : 1)) / 2;
    }
    // Both outcomes occur often.
    EXPECT_GT(found, possible / 20);
    EXPECT_LT(found, possible / 2);
}

TEST(SweepAndPrune, TouchingBoxesOverlap) {
    const std::vector<Eigen::AlignedBox3d> boxes = {
        {Vec3(0, 0, 0), Vec3(1, 1, 1)},
        {Vec3(1, 1, 1), Vec3(2, 2, 2)},          // touches box 0 at a corner
        {Vec3(2, 0, 0), Vec3(3, 1, 1)},          // touches box 1 along an edge, apart from 0
        {Vec3(3.5, 0, 0), Vec3(4, 1, 1)},        // apart from all
    };
    EXPECT_EQ(find_object_pairs(boxes, false), (std::vector<ObjectPair>{{0, 1}, {1, 2}}));
}

TEST(SweepAndPrune, SelfCollisionAddsEveryObject) {
    const std::vector<Eigen::AlignedBox3d> boxes = {
        {Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(5, 5, 5), Vec3(6, 6, 6)}, {Vec3(0.5, 0, 0), Vec3(2, 1, 1)}};
    EXPECT_EQ(find_object_pairs(boxes, true), (std::vector<ObjectPair>{{0, 0}, {0, 2}, {1, 1}, {2, 2}}));
}

TEST(SweepAndPrune, EmptyBoxesOverlapNothing) {
    Eigen::AlignedBox3d empty;
    empty.setEmpty();
    const std::vector<Eigen::AlignedBox3d> boxes = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, empty};
    EXPECT_TRUE(find_object_pairs(boxes, false).empty());
}

TEST(ObjectBoxes, CoverEveryVertex) {
    const Frame frame = testing::make_frame(
        {testing::grid_sheet(2, 1.0), testing::grid_sheet(3, 2.0, Vec3(-1, 5, 2))});
    const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
    ASSERT_EQ(boxes.size(), 2u);
    EXPECT_EQ(boxes[0].min(), Vec3(0, 0, 0));
    EXPECT_EQ(boxes[0].max(), Vec3(1, 1, 0));
    EXPECT_EQ(boxes[1].min(), Vec3(-1, 5, 2));
    EXPECT_EQ(boxes[1].max(), Vec3(1, 7, 2));
}

}  // namespace
}  // namespace collidescope
