// record --regions: /regions (schema 1.5, measures widened in 1.6) holds, frame by frame, what find_regions and
// RegionTracker give on the same frames (ids, counts, measures and curve points bit for bit);
// validate checks it and names a broken offset; a recording without --regions has none; join
// refuses parts with regions.

#include "recording_helpers.hpp"
#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/recorder/validate.hpp"
#include "collidescope/regions.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

TEST(RecordRegions, RegionsEqualTheEnginesFrameByFrame) {
    TempDir dir;
    const auto result = run_cli({"record", "--scene", "E4:small", "--self", "--frames", "0:8", "--regions", "-o", "r.h5", "-q"},
                                dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const recorder::Recording rec(dir.path() / "r.h5");
    ASSERT_TRUE(rec.has_regions());
    EXPECT_EQ(rec.version_minor(), recorder::schema::k_version_minor);
    ASSERT_EQ(rec.frames_complete(), 8u);

    Scene scene = make_builtin_scene("E4:small");
    Pipeline pipeline({"aabb", true, 0});
    RegionTracker tracker;
    std::size_t compared = 0;
    for (std::uint32_t f = 0; f < 8; ++f) {
        const Frame frame = scene.source->frame(f);
        std::vector<Region> expected = find_regions(frame, pipeline.process(frame).colliding_pairs);
        tracker.update(f, expected);
        const std::vector<recorder::RecordedRegion> got = rec.regions(f);
        ASSERT_EQ(got.size(), expected.size()) << "frame " << f;
        for (std::size_t k = 0; k < got.size(); ++k) {
            const Region& e = expected[k];
            const recorder::RecordedRegion& g = got[k];
            SCOPED_TRACE("frame " + std::to_string(f) + " region " + std::to_string(k));
            EXPECT_EQ(g.id, e.id);
            EXPECT_EQ(g.obj_a, e.obj_a);
            EXPECT_EQ(g.obj_b, e.obj_b);
            EXPECT_EQ(g.pairs, e.pairs);
            EXPECT_EQ(g.triangles_a, e.triangles_a.size());
            EXPECT_EQ(g.triangles_b, e.triangles_b.size());
            EXPECT_EQ(g.loops, e.loops);
            EXPECT_EQ(g.curve_length, e.curve_length);
            EXPECT_EQ(g.coplanar_area, e.coplanar_area);
            const auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
            EXPECT_TRUE(same(g.inside_area_a, e.inside_area_a));
            EXPECT_TRUE(same(g.inside_area_b, e.inside_area_b));
            EXPECT_TRUE(same(g.depth, e.depth));
            EXPECT_EQ(g.box[0], e.box.min().x());
            EXPECT_EQ(g.box[5], e.box.max().z());
            EXPECT_EQ(g.predecessors, e.predecessors);
            ASSERT_EQ(g.curves.size(), e.curves.size());
            for (std::size_t c = 0; c < g.curves.size(); ++c) {
                EXPECT_EQ(g.curves[c].closed, e.curves[c].closed);
                ASSERT_EQ(g.curves[c].xyz.size(), 3 * e.curves[c].points.size());
                for (std::size_t p = 0; p < e.curves[c].points.size(); ++p) {
                    EXPECT_EQ(g.curves[c].xyz[3 * p + 1], e.curves[c].points[p].y());
                }
            }
            ++compared;
        }
    }
    EXPECT_GT(compared, 100u);
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
    const auto inspect = run_cli({"inspect", "r.h5"}, dir.path());
    EXPECT_NE(inspect.out.find("regions: " + std::to_string(tracker.tracks().size()) + " over the run"), std::string::npos)
        << inspect.out;
}

TEST(RecordRegions, ABrokenOffsetIsNamed) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--regions", "-o", "r.h5", "-q"}, dir.path()).exit_code, 0);
    const std::filesystem::path file = dir.path() / "r.h5";
    testing::overwrite_u64(file, recorder::schema::k_region_curve_offsets, 1, 1u << 30);
    const recorder::Recording rec(file);
    const recorder::ValidationReport report = recorder::validate_recording(rec);
    ASSERT_FALSE(report.problems.empty());
    EXPECT_NE(report.problems.front().find("/regions/curve_offsets"), std::string::npos) << report.problems.front();
    const auto validate = run_cli({"validate", "r.h5"}, dir.path());
    EXPECT_NE(validate.exit_code, 0);
}

TEST(RecordRegions, OnlyWithTheFlagAndNeverJoined) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "0:8", "-o", "plain.h5", "-q"}, dir.path()).exit_code, 0);
    EXPECT_FALSE(recorder::Recording(dir.path() / "plain.h5").has_regions());
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "0:8", "--regions", "-o", "a.h5", "-q"}, dir.path()).exit_code, 0);
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "8:16", "--regions", "-o", "b.h5", "-q"}, dir.path()).exit_code, 0);
    const auto join = run_cli({"join", "a.h5", "b.h5", "-o", "joined.h5"}, dir.path());
    EXPECT_EQ(join.exit_code, 2);
    EXPECT_NE(join.err.find("holds /regions"), std::string::npos) << join.err;
}

}  // namespace
}  // namespace collidescope
