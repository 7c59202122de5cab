// `collidescope check` end to end on scenes generated here and written as PLY frame
// sequences: the pairs TSV against the all-pairs reference, the stats JSON Lines, --frames,
// exit codes, stdout and stderr.

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <thread>
#include <string_view>

namespace collidescope {
namespace {

using testing::FramePair;
using testing::run_cli;
using testing_files::TempDir;

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The TSV lines of frames [begin, end) of `pairs`.
std::vector<FramePair> frames_between(const std::vector<FramePair>& pairs, std::uint32_t begin, std::uint32_t end) {
    std::vector<FramePair> kept;
    std::copy_if(pairs.begin(), pairs.end(), std::back_inserter(kept),
                 [&](const FramePair& p) { return p.frame >= begin && p.frame < end; });
    return kept;
}

TEST(CheckCli, PairsMatchReferenceOnGeneratedScenes) {
    for (const bool self_collision : {false, true}) {
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            SCOPED_TRACE("seed " + std::to_string(seed) + (self_collision ? ", --self" : ""));
            const TempDir dir;
            const Scene scene = testing::random_scene(seed, {3, 3, 40, 5});
            const std::vector<std::string> inputs = testing::write_scene_files(scene, dir.path(), 1);
            std::vector<std::string> args = {"check", "--pairs", "pairs.tsv"};
            if (self_collision) args.push_back("--self");
            const testing::CliResult result = run_cli(concat(args, inputs), dir.path());
            const std::vector<FramePair> expected = testing::reference_frame_pairs(scene, self_collision);
            EXPECT_EQ(result.exit_code, expected.empty() ? 0 : 1) << result.err;
            EXPECT_EQ(testing::parse_pairs_tsv(testing::read_text(dir / "pairs.tsv")), expected);
            EXPECT_TRUE(result.out.empty());
        }
    }
}

TEST(CheckCli, PairsTsvIsSortedCanonicalAndUnique) {
    const TempDir dir;
    const Scene scene = testing::random_scene(9, {4, 3, 60, 6});
    const testing::CliResult result =
        run_cli(concat({"check", "--self", "--pairs", "-"}, testing::write_scene_files(scene, dir.path())), dir.path());
    ASSERT_EQ(result.exit_code, 1) << result.err;
    const std::vector<FramePair> pairs = testing::parse_pairs_tsv(result.out);
    ASSERT_GT(pairs.size(), 10u);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const TrianglePair& p = pairs[k].pair;
        EXPECT_LT(std::tie(p.obj_a, p.tri_a), std::tie(p.obj_b, p.tri_b)) << "line " << k + 1;
        if (k > 0) {
            EXPECT_LT(pairs[k - 1], pairs[k]) << "line " << k + 1;
        }
    }
}

// An output that is a device or a pipe (/dev/null, a FIFO) is written in place: no .partial
// beside it, no rename over it, and it is still a pipe afterwards (as root, the rename would
// have replaced /dev/null with a file).
TEST(CheckCli, OutputsToAPipeAreWrittenInPlace) {
    TempDir dir;
    const std::filesystem::path fifo = dir.path() / "pairs.fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo);
        received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    });
    const auto result = run_cli({"check", "--scene", "C:small", "--pairs", fifo.string(),
                                 "--exit-zero", "-q"}, dir.path());
    reader.join();
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    EXPECT_FALSE(received.empty());
    EXPECT_EQ(std::count(received.begin(), received.end(), '\n'), 184);  // C:small's pairs
}

TEST(CheckCli, StatsJsonLinesOneObjectPerFrame) {
    const TempDir dir;
    const Scene scene = testing::random_scene(3, {3, 4, 40, 5});
    const testing::CliResult result = run_cli(
        concat({"check", "--stats", "stats.jsonl", "--pairs", "pairs.tsv"}, testing::write_scene_files(scene, dir.path())),
        dir.path());
    ASSERT_NE(result.exit_code, 2) << result.err;
    const std::vector<FramePair> pairs = testing::parse_pairs_tsv(testing::read_text(dir / "pairs.tsv"));
    std::istringstream lines(testing::read_text(dir / "stats.jsonl"));
    std::uint32_t frame = 0;
    for (std::string line; std::getline(lines, line); ++frame) {
        SCOPED_TRACE(line);
        const nlohmann::json stats = nlohmann::json::parse(line);
        EXPECT_EQ(stats.at("frame"), frame);
        EXPECT_EQ(stats.at("method"), "adaptive");  // the default method
        EXPECT_TRUE(stats.at("decision").at("reason").is_string());
        // The stages are timed one after the other inside `total`'s span: each is positive
        // (every frame updates its objects) and together they fit in the total.
        double stages = 0;
        for (const char* stage : {"update", "object_level", "cull", "narrow", "total"}) {
            ASSERT_TRUE(stats.at("ms").at(stage).is_number()) << stage;
            const double ms = stats.at("ms").at(stage).get<double>();
            if (std::string_view(stage) == "total") {
                EXPECT_GE(ms, stages * (1 - 1e-12)) << "the stages add up to more than the total";
            } else {
                stages += ms;
            }
        }
        EXPECT_GT(stats.at("ms").at("update").get<double>(), 0.0);
        const nlohmann::json& counts = stats.at("counts");
        for (const char* count : {"triangles", "object_pairs", "box_tests", "candidate_pairs", "exact_tests",
                                  "exact_fallbacks", "colliding_pairs"}) {
            ASSERT_TRUE(counts.at(count).is_number_unsigned()) << count;
        }
        EXPECT_EQ(counts.at("colliding_pairs").get<std::size_t>(), frames_between(pairs, frame, frame + 1).size());
        EXPECT_EQ(counts.at("exact_tests"), counts.at("candidate_pairs"));
        EXPECT_GE(counts.at("candidate_pairs").get<std::uint64_t>(), counts.at("colliding_pairs").get<std::uint64_t>());
    }
    EXPECT_EQ(frame, 4u);
}

TEST(CheckCli, FramesSelectsAHalfOpenRange) {
    const TempDir dir;
    const Scene scene = testing::random_scene(2, {3, 5, 40, 5});
    const std::vector<std::string> inputs = testing::write_scene_files(scene, dir.path(), 10);
    const std::vector<FramePair> all = testing::reference_frame_pairs(scene, false);
    const struct {
        const char* spec;
        std::uint32_t begin, end;
    } cases[] = {{"1:3", 1, 3}, {"2", 2, 3}, {":2", 0, 2}, {"3:", 3, 5}, {":", 0, 5}, {"0:5", 0, 5}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.spec);
        const testing::CliResult result =
            run_cli(concat({"check", "--exit-zero", "--frames", c.spec, "--pairs", "-", "--stats", "stats.jsonl"}, inputs),
                    dir.path());
        ASSERT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(testing::parse_pairs_tsv(result.out), frames_between(all, c.begin, c.end));
        std::istringstream stats(testing::read_text(dir / "stats.jsonl"));
        std::vector<std::uint32_t> frames;
        for (std::string line; std::getline(stats, line);) frames.push_back(nlohmann::json::parse(line).at("frame"));
        ASSERT_EQ(frames.size(), c.end - c.begin);
        EXPECT_EQ(frames.front(), c.begin);
    }
    for (const char* bad : {"5", "0:6", "3:3", "4:2", "x", "1:2:3", "-1", "1-3"}) {
        SCOPED_TRACE(bad);
        const testing::CliResult result = run_cli(concat({"check", "--frames", bad}, inputs), dir.path());
        EXPECT_EQ(result.exit_code, 2);
        ASSERT_EQ(result.err_lines().size(), 1u) << result.err;
        EXPECT_NE(result.err.find("--frames"), std::string::npos) << result.err;
    }
}

TEST(CheckCli, ExitCodesFollowCollisions) {
    const TempDir dir;
    // Two sheets apart: no collisions. The same sheets crossing: collisions.
    MeshData sheet = testing::grid_sheet(3, 1.0);
    write_ply(dir / "a.ply", sheet);
    write_ply(dir / "far.ply", testing::translated(sheet, Vec3(0, 0, 5)));
    write_ply(dir / "near.ply", testing::translated(sheet, Vec3(0.5, 0.5, 0)));
    const testing::CliResult apart = run_cli({"check", "a.ply", "far.ply"}, dir.path());
    EXPECT_EQ(apart.exit_code, 0) << apart.err;
    const testing::CliResult crossing = run_cli({"check", "a.ply", "near.ply"}, dir.path());
    EXPECT_EQ(crossing.exit_code, 1) << crossing.err;
    const testing::CliResult forgiven = run_cli({"check", "--exit-zero", "a.ply", "near.ply"}, dir.path());
    EXPECT_EQ(forgiven.exit_code, 0) << forgiven.err;
    const testing::CliResult broken = run_cli({"check", "--exit-zero", "a.ply", "missing.ply"}, dir.path());
    EXPECT_EQ(broken.exit_code, 2) << broken.err;
}

TEST(CheckCli, StderrHasOneLinePerFrameAndATotal) {
    const TempDir dir;
    const Scene scene = testing::random_scene(4, {2, 3, 20, 4});
    const std::vector<std::string> inputs = testing::write_scene_files(scene, dir.path());
    const testing::CliResult result = run_cli(concat({"check", "--exit-zero"}, inputs), dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(result.out.empty()) << "data on stdout only when asked for";
    const std::vector<std::string> lines = result.err_lines();
    ASSERT_EQ(lines.size(), 1u + 3u + 1u) << result.err;  // scene, frames, total
    for (std::uint32_t f = 0; f < 3; ++f) {
        const std::size_t pairs = testing::reference_colliding_pairs(scene.source->frame(f), false).size();
        EXPECT_EQ(lines[1 + f].rfind("frame " + std::to_string(f) + ": " + std::to_string(pairs) + " colliding pairs, ", 0), 0u)
            << lines[1 + f];
    }
    EXPECT_EQ(lines.back().rfind("total: 3 frames, ", 0), 0u) << lines.back();
    const testing::CliResult quiet = run_cli(concat({"check", "--exit-zero", "--quiet"}, inputs), dir.path());
    ASSERT_EQ(quiet.err_lines().size(), 1u) << quiet.err;
    const auto without_ms = [](const std::string& line) { return line.substr(0, line.rfind(',')); };
    EXPECT_EQ(without_ms(quiet.err_lines()[0]), without_ms(lines.back()));
}

TEST(CheckCli, ThreadCountsGiveIdenticalPairs) {
    const TempDir dir;
    const Scene scene = testing::random_scene(12, {4, 2, 80, 8});
    const std::vector<std::string> inputs = testing::write_scene_files(scene, dir.path());
    const testing::CliResult one = run_cli(concat({"check", "--self", "--threads", "1", "--pairs", "-"}, inputs), dir.path());
    const testing::CliResult two = run_cli(concat({"check", "--self", "--threads", "2", "--pairs", "-"}, inputs), dir.path());
    ASSERT_EQ(one.exit_code, 1) << one.err;
    EXPECT_EQ(two.exit_code, 1) << two.err;
    EXPECT_EQ(one.out, two.out);
}

TEST(CheckCli, BuiltinDemoSceneMatchesReference) {
    const TempDir dir;
    const testing::CliResult result = run_cli({"check", "--scene", "demo:small", "--pairs", "-"}, dir.path());
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(testing::parse_pairs_tsv(result.out),
              testing::reference_frame_pairs(make_builtin_scene("demo:small"), false));
    EXPECT_NE(result.err.find("scene 'demo' (small)"), std::string::npos) << result.err;
}

TEST(CheckCli, ManifestSelfFlagAndOverrides) {
    const TempDir dir;
    std::mt19937_64 rng(5);
    MeshData crumpled = testing::crumpled_sheet(rng, 8, 1.0, true);
    std::filesystem::create_directories(dir / "cache");
    for (int f = 0; f < 2; ++f) {
        write_ply(dir / ("cache/cloth." + std::to_string(f) + ".ply"), testing::translated(crumpled, Vec3(f, 0, 0)));
    }
    testing_files::write_text(dir / "cache/scene.json",
                              R"({"name": "folds", "frames": 2, "objects": [{"name": "cloth", "pattern": "cloth.%d.ply"}], "self": true})");
    const Frame frame = testing::make_frame({crumpled});
    const std::size_t self_pairs = testing::reference_colliding_pairs(frame, true).size();
    ASSERT_GT(self_pairs, 0u) << "the crumpled sheet must fold over itself";

    const testing::CliResult with_self = run_cli({"check", "--pairs", "-", "cache/scene.json"}, dir.path());
    EXPECT_EQ(with_self.exit_code, 1) << with_self.err;
    EXPECT_EQ(testing::parse_pairs_tsv(with_self.out).size(), 2 * self_pairs);
    const testing::CliResult without = run_cli({"check", "--no-self", "--pairs", "-", "cache/scene.json"}, dir.path());
    EXPECT_EQ(without.exit_code, 0) << without.err;
    EXPECT_TRUE(without.out.empty());
}

}  // namespace
}  // namespace collidescope
