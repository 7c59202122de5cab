// `check --between-frames`: the pairs file (the per-frame columns, then toi and the
// pass-through flag) equals the library's BetweenFrames on the same frames; stats per
// interval; the total line; one-line errors for a single frame, a topology change, a
// coordinate that is not finite, and --regions with it.

#include "support/cli_runner.hpp"
#include "check_between.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/datasets.hpp"
#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

TEST(CheckBetweenFrames, PairsAndStatsEqualTheLibraryIntervalByInterval) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo", "--between-frames", "--threads", "2", "--pairs", "pairs.tsv",
                                 "--stats", "stats.jsonl"},
                                dir.path());
    ASSERT_EQ(result.exit_code, 1) << result.err;
    EXPECT_NE(result.err.find("pass-throughs (apart at both frames); tolerance"), std::string::npos) << result.err;

    std::ostringstream expected;
    const Scene scene = make_builtin_scene("demo");
    BetweenFrames detector;
    std::uint64_t pass_throughs = 0;
    Frame from = scene.source->frame(0);
    for (std::uint32_t f = 0; f + 1 < scene.source->frame_count(); ++f) {
        Frame to = scene.source->frame(f + 1);
        for (const IntervalContact& c : detector.detect(from, to).contacts) {
            char line[160];
            std::snprintf(line, sizeof line, "%u\t%u\t%u\t%u\t%u\t%.9f\t%d\n", f, c.pair.obj_a, c.pair.tri_a, c.pair.obj_b,
                          c.pair.tri_b, app::printed_toi(c.toi, 1e-9), c.pass_through ? 1 : 0);
            unsigned k = 0, oa = 0, ta = 0, ob = 0, tb = 0;
            double printed = 0;
            int pass = 0;
            ASSERT_EQ(std::sscanf(line, "%u %u %u %u %u %lf %d", &k, &oa, &ta, &ob, &tb, &printed, &pass), 7) << line;
            EXPECT_LE(printed, c.toi) << line;  // still a lower bound as printed
            expected << line;
            pass_throughs += c.pass_through;
        }
        from = std::move(to);
    }
    EXPECT_GT(pass_throughs, 0u);
    EXPECT_EQ(testing::read_text(dir.path() / "pairs.tsv"), expected.str());

    std::ifstream stats(dir.path() / "stats.jsonl");
    std::uint64_t intervals = 0, counted = 0;
    for (std::string line; std::getline(stats, line); ++intervals) {
        const nlohmann::json row = nlohmann::json::parse(line);
        EXPECT_EQ(row["interval"][0].get<std::uint32_t>(), intervals);
        EXPECT_EQ(row["interval"][1].get<std::uint32_t>(), intervals + 1);
        EXPECT_GT(row["tolerance"].get<double>(), 0);
        EXPECT_LE(row["counts"]["contacts"].get<std::uint64_t>(), row["counts"]["candidate_pairs"].get<std::uint64_t>());
        counted += row["counts"]["pass_throughs"].get<std::uint64_t>();
    }
    EXPECT_EQ(intervals, scene.source->frame_count() - 1);
    EXPECT_EQ(counted, pass_throughs);
}

// A one-line error on stderr, exit 2, containing `needle`.
void expect_error(const testing::CliResult& result, const std::string& needle) {
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

TEST(CheckBetweenFrames, BadRangesAndInputsAreOneLineErrors) {
    TempDir dir;
    expect_error(run_cli({"check", "--scene", "demo", "--between-frames", "--frames", "3"}, dir.path()),
                 "needs at least two frames");
    expect_error(run_cli({"check", "--scene", "demo", "--between-frames", "--regions", "r.jsonl"}, dir.path()),
                 "--regions and --between-frames");
    expect_error(run_cli({"check", "--scene", "demo", "--between-frames", "--ccd-tolerance", "-1"}, dir.path()),
                 "--ccd-tolerance");

    // Frame 1 of a sequence has another mesh.
    MeshData small;
    small.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    small.triangles = {{0, 1, 2}};
    MeshData larger = small;
    larger.vertices.push_back({1, 1, 0});
    larger.triangles.push_back({1, 3, 2});
    write_ply(dir.path() / "m.0000.ply", small);
    write_ply(dir.path() / "m.0001.ply", larger);
    expect_error(run_cli({"check", "m.%04d.ply", "--between-frames"}, dir.path()), "changes its mesh between frames 0 and 1");

    // A coordinate that is not finite in the second frame.
    MeshData broken = small;
    broken.vertices[1].x() = std::nan("");
    write_ply(dir.path() / "n.0000.ply", small);
    write_ply(dir.path() / "n.0001.ply", broken);
    const auto nan = run_cli({"check", "n.%04d.ply", "--between-frames"}, dir.path());
    EXPECT_EQ(nan.exit_code, 2) << nan.err;
    EXPECT_NE(nan.err.find("n.0001.ply"), std::string::npos) << nan.err;
}

}  // namespace
}  // namespace collidescope
