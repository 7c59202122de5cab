// `check --regions`: JSON Lines of the frame's regions with ids that follow them over frames,
// equal to the engine's find_regions + RegionTracker on the same frames; the region lines at
// the end; usage errors.

#include "support/cli_runner.hpp"
#include "support/testmodels.hpp"
#include "mesh/temp_files.hpp"

#include "check_regions.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/regions.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;


std::vector<nlohmann::json> read_lines(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<nlohmann::json> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

TEST(CheckRegions, LinesEqualTheEnginesRegionsFrameByFrame) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "C:small", "--method", "aabb", "--regions", "regions.jsonl"}, dir.path());
    ASSERT_EQ(result.exit_code, 1) << result.err;  // C collides
    const std::vector<nlohmann::json> lines = read_lines(dir.path() / "regions.jsonl");

    // The same frames through the library.
    Scene scene = make_builtin_scene("C:small");
    Pipeline pipeline({"aabb", false, 0});
    RegionTracker tracker;
    std::vector<std::string> expected;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        const std::vector<TrianglePair> pairs = pipeline.process(frame).colliding_pairs;
        std::vector<Region> regions = find_regions(frame, pairs);
        tracker.update(f, regions);
        for (const Region& region : regions) expected.push_back(app::region_json(f, region, {"sheet_0", "sheet_1"}));
    }
    ASSERT_EQ(lines.size(), expected.size());
    ASSERT_FALSE(lines.empty());
    for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i], nlohmann::json::parse(expected[i])) << i;
    for (const nlohmann::json& line : lines) {
        EXPECT_GE(line["region"].get<int>(), 1);
        EXPECT_GT(line["pairs"].get<int>(), 0);
        EXPECT_GT(line["curve_length"].get<double>(), 0.0);
        ASSERT_FALSE(line["curves"].empty());
    }
    // One line per region on stderr, then the count.
    for (const RegionTrack& track : tracker.tracks()) {
        EXPECT_NE(result.err.find("region " + std::to_string(track.id) + ": objects 'sheet_0' and 'sheet_1', frames " +
                                  std::to_string(track.first_frame) + "-" + std::to_string(track.last_frame)),
                  std::string::npos)
            << result.err;
    }
    EXPECT_NE(result.err.find(std::to_string(tracker.tracks().size()) + " regions over the run"), std::string::npos);
}

TEST(CheckRegions, AClosedObjectGivesInsideAreasAndADepth) {
    // The demo's torus is closed, its sheet open: the sheet's surface inside the torus has an
    // area, the torus's inside the sheet has none (null), and the depth is defined.
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo:small", "--frames", "8:14", "--regions", "r.jsonl"}, dir.path());
    ASSERT_EQ(result.exit_code, 1) << result.err;
    const std::vector<nlohmann::json> lines = read_lines(dir.path() / "r.jsonl");
    ASSERT_FALSE(lines.empty());
    double deepest = 0;
    for (const nlohmann::json& line : lines) {
        ASSERT_TRUE(line["depth"].is_number()) << line.dump();
        EXPECT_TRUE(line["inside_area"][0].is_null() != line["inside_area"][1].is_null()) << line.dump();
        deepest = std::max(deepest, line["depth"].get<double>());
    }
    EXPECT_GT(deepest, 0.0);
    EXPECT_NE(result.err.find(" deep at most (frame "), std::string::npos) << result.err;
}

TEST(CheckRegions, SelfContactRegionsNameOneObject) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "E4:small", "--self", "--frames", "0:2", "--regions", "-",
                                 "--exit-zero", "-q"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::istringstream out(result.out);
    std::size_t self = 0;
    for (std::string line; std::getline(out, line);) {
        const nlohmann::json region = nlohmann::json::parse(line);
        self += region["objects"][0] == region["objects"][1];
    }
    EXPECT_GT(self, 0u) << result.out.substr(0, 500);
}

// An animated character of assimp-testmodels, with self-contact: regions within one body
// part and between parts, each followed over the clip.
TEST(CheckRegions, AnimatedCharacterHasSelfAndBetweenPartRegions) {
    REQUIRE_TESTMODEL(model, "X/BCN_Epileptic.X");
    TempDir dir;
    const auto result = run_cli({"check", model.string(), "--self", "--fps", "30", "--frames", "30:50", "--regions",
                                 "regions.jsonl", "--exit-zero", "-q"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::size_t self = 0, between = 0;
    std::uint32_t last_frame = 0;
    for (const nlohmann::json& region : read_lines(dir.path() / "regions.jsonl")) {
        (region["objects"][0] == region["objects"][1] ? self : between) += 1;
        EXPECT_GE(region["frame"].get<std::uint32_t>(), last_frame);
        last_frame = region["frame"].get<std::uint32_t>();
        EXPECT_GE(region["curve_length"].get<double>(), 0.0);
    }
    EXPECT_GT(self, 0u);
    EXPECT_GT(between, 0u);
}

TEST(CheckRegions, OnlyOneOutputOnStdout) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "C:small", "--regions", "-", "--pairs", "-"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("only one of them can write to stdout"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace collidescope
