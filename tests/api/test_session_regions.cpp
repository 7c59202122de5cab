// Session::regions (SessionOptions::regions): each step's regions equal find_regions and
// RegionTracker on the same frames, as plain data; empty without the option; recorded too.

#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/regions.hpp"
#include "collidescope/session.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

TEST(SessionRegions, EachStepEqualsTheEnginesRegions) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const bool self = seed % 2 == 0;
        const Scene scene = testing::random_scene(seed, {.objects = 3, .frames = 4});
        const std::vector<Frame> frames = testing::all_frames(scene);
        testing_files::TempDir dir;
        Session session({.method = "aabb", .self_collision = self, .record = (dir.path() / "r.h5").string(), .regions = true});
        Session plain({.method = "aabb", .self_collision = self});
        for (const ObjectFrame& object : frames[0].objects) {
            session.add_object(object.topology->triangles);
            plain.add_object(object.topology->triangles);
        }
        RegionTracker tracker;
        std::size_t compared = 0;
        for (const Frame& frame : frames) {
            std::vector<VertexView> views;
            for (const ObjectFrame& object : frame.objects) views.push_back(vertex_view(object.vertices.front().data(), object.vertices.size()));
            const std::span<const CollidingPair> pairs = session.step(views);
            plain.step(views);
            EXPECT_TRUE(plain.regions().empty());
            std::vector<TrianglePair> engine_pairs;
            for (const CollidingPair& p : pairs) engine_pairs.push_back({p.obj_a, p.tri_a, p.obj_b, p.tri_b});
            std::vector<Region> expected = find_regions(frame, engine_pairs);
            tracker.update(frame.index, expected);
            const std::span<const StepRegion> got = session.regions();
            ASSERT_EQ(got.size(), expected.size()) << "seed " << seed << " frame " << frame.index;
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_EQ(got[k].id, expected[k].id);
                EXPECT_EQ(got[k].pairs, expected[k].pairs);
                EXPECT_EQ(got[k].curve_length, expected[k].curve_length);
                EXPECT_EQ(got[k].curves.size(), expected[k].curves.size());
                EXPECT_EQ(got[k].predecessors, expected[k].predecessors);
                EXPECT_EQ(got[k].box_max[2], expected[k].box.max().z());
                const auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
                EXPECT_TRUE(same(got[k].depth, expected[k].depth));
                EXPECT_TRUE(same(got[k].inside_area_a, expected[k].inside_area_a));
                EXPECT_TRUE(same(got[k].inside_area_b, expected[k].inside_area_b));
                ++compared;
            }
        }
        session.close();
        const recorder::Recording recording(dir.path() / "r.h5");
        EXPECT_TRUE(recording.has_regions());
        std::size_t recorded = 0;
        for (std::uint64_t row = 0; row < recording.frames_complete(); ++row) recorded += recording.regions(row).size();
        EXPECT_EQ(recorded, compared) << "seed " << seed;
    }
}

}  // namespace
}  // namespace collidescope
