// `collidescope export` and `collidescope bench` end to end on the small data sets: exported
// files read back as exactly the generated frames, and bench writes every file it promises.

#include "support/cli_runner.hpp"
#include "support/sweep_size.hpp"
#include "mesh/temp_files.hpp"

#include "bench_report.hpp"
#include "bench_run.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace collidescope {
namespace {

using testing::line_count;
using testing::read_text;
using testing::run_cli;
using testing_files::TempDir;

// The scene, or a failure naming why it is unavailable (a data package not installed:
// scripts/setup.sh installs them all).
#define MAKE_SCENE_OR_FAIL(var, spec)                                   \
    Scene var;                                                          \
    try {                                                               \
        var = make_builtin_scene(spec);                                 \
    } catch (const UnavailableError& error) {                           \
        FAIL() << error.what();                                         \
    }

class ExportRoundTrip : public ::testing::TestWithParam<std::string> {};

// export then check on the files gives exactly the pairs of check --scene (self-collision as the
// scene sets it, which the manifest carries).
TEST_P(ExportRoundTrip, CheckOnExportedFilesFindsTheScenesPairs) {
    const std::string spec = GetParam() + ":small";
    MAKE_SCENE_OR_FAIL(scene, spec);
    TempDir dir;
    const auto exported = run_cli({"export", spec, "-o", "out"}, dir.path());
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    const auto from_files = run_cli({"check", "out/scene.json", "--pairs", "files.tsv", "--exit-zero", "-q"}, dir.path());
    const auto from_scene = run_cli({"check", "--scene", spec, "--pairs", "scene.tsv", "--exit-zero", "-q"}, dir.path());
    ASSERT_EQ(from_files.exit_code, 0) << from_files.err;
    ASSERT_EQ(from_scene.exit_code, 0) << from_scene.err;
    const std::string expected = read_text(dir.path() / "scene.tsv");
    EXPECT_GT(line_count(expected), 0u) << spec << " has no collisions at all";
    EXPECT_EQ(read_text(dir.path() / "files.tsv"), expected) << spec;

    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path() / "out/scene.json"));
    EXPECT_EQ(manifest["frames"], scene.source->frame_count());
    EXPECT_EQ(manifest["self"], scene.self_collision);
    EXPECT_EQ(manifest["objects"].size(), scene.source->object_count());
}

INSTANTIATE_TEST_SUITE_P(DataSets, ExportRoundTrip, ::testing::Values("A", "B", "C", "D", "E1"),
                         [](const auto& param_info) { return param_info.param; });

// Every exported frame file holds exactly the generated vertices and triangles, including across
// D's topology change.
TEST(Export, FilesHoldTheGeneratedFramesBitForBit) {
    MAKE_SCENE_OR_FAIL(scene, "D:small");
    TempDir dir;
    ASSERT_EQ(run_cli({"export", "D:small", "-o", "out", "-q"}, dir.path()).exit_code, 0);
    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path() / "out/scene.json"));
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        for (std::uint32_t o = 0; o < frame.objects.size(); ++o) {
            char name[256];
            std::snprintf(name, sizeof name, manifest["objects"][o]["pattern"].get<std::string>().c_str(), f);
            const MeshData mesh = read_mesh_file(dir.path() / "out" / name);
            EXPECT_EQ(mesh.vertices, frame.objects[o].vertices) << name;
            EXPECT_EQ(mesh.triangles, frame.objects[o].topology->triangles) << name;
        }
    }
}

TEST(Export, FramesRangeIsRenumberedFromZero) {
    TempDir dir;
    const auto result = run_cli({"export", "C:small", "-o", "out", "--frames", "4:7", "-q"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path() / "out/scene.json"));
    EXPECT_EQ(manifest["frames"], 3);
    std::string stem = manifest["objects"][0]["pattern"].get<std::string>();
    stem = stem.substr(0, stem.find(".%04d.ply"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / (stem + ".0002.ply"))) << stem;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / (stem + ".0003.ply"))) << stem;
}

TEST(Export, UnknownSceneIsAnErrorNamingTheKnownOnes) {
    TempDir dir;
    const auto result = run_cli({"export", "Z", "-o", "out"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("known: A, B"), std::string::npos) << result.err;
}

// bench on two small scenes writes frames.csv, summary.csv, a plot per scene and index.html,
// prints the table and says the methods agreed. Two repeats (one in a sanitizer build: the files
// hold a row per frame and method whatever the repeats).
TEST(Bench, TwoSmallScenesProduceEveryFile) {
    TempDir dir;
    const std::string repeats = std::to_string(testing::sweep_size(2, 2));
    const auto result = run_cli({"bench", "--scenes", "C,D", "--preset", "small", "--repeat", repeats, "-o", "out"},
                                dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::filesystem::path out = dir.path() / "out";
    const std::size_t methods = method_names().size() - 1;  // all but "adaptive" (= adaptive-cost)
    const std::size_t frames = make_builtin_scene("C:small").source->frame_count() +
                               make_builtin_scene("D:small").source->frame_count();
    EXPECT_EQ(line_count(read_text(out / "frames.csv")), 1 + frames * methods);
    EXPECT_EQ(line_count(read_text(out / "summary.csv")), 1 + 2 * methods);
    for (const char* plot : {"time_C_small.svg", "time_D_small.svg"}) {
        const std::string svg = read_text(out / plot);
        EXPECT_NE(svg.find("id=\"line2d_"), std::string::npos) << plot;  // a method's line (matplotlib)
        EXPECT_NE(svg.find(">aabb</text>"), std::string::npos) << plot;  // its legend entry
        EXPECT_NE(read_text(out / "index.html").find(plot), std::string::npos) << plot;
    }
    EXPECT_NE(result.out.find("C:small"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("D:small"), std::string::npos) << result.out;
    EXPECT_NE(result.err.find("identical pairs"), std::string::npos) << result.err;
}

// The plotting script refuses a frames.csv it cannot read with one line naming the file, and
// bench reports that as an error (the CSVs stay).
TEST(Bench, PlotsOfAnUnreadableFramesFileFailWithTheFileNamed) {
    TempDir dir;
    std::ofstream(dir.path() / "frames.csv") << "scene,preset,method,frame\nC,small,aabb,0\n";
    try {
        app::draw_plots(dir.path());
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("drawing the plots failed"), std::string::npos) << error.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "time_C_small.svg"));
}

TEST(Bench, BruteIsSkippedOnLargerPresetsUnlessNamed) {
    TempDir dir;
    const auto result = run_cli({"bench", "--scenes", "C:default", "--methods", "brute", "--frames", "0:2",
                                 "--repeat", "1", "-o", "out"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("C:default"), std::string::npos) << result.out;
}

TEST(Bench, ComparePairListsCountsMissingAndExtra) {
    const std::vector<TrianglePair> reference = {{0, 1, 1, 2}, {0, 1, 1, 3}, {0, 4, 1, 0}};
    const std::vector<TrianglePair> pairs = {{0, 1, 1, 3}, {0, 4, 1, 0}, {0, 5, 1, 0}, {0, 6, 1, 0}};
    const app::BenchMismatch m = app::compare_pair_lists(reference, pairs);
    EXPECT_EQ(m.missing, 1u);
    EXPECT_EQ(m.extra, 2u);
    const app::BenchMismatch same = app::compare_pair_lists(reference, reference);
    EXPECT_EQ(same.missing + same.extra, 0u);
}

TEST(Bench, RunsEachMethodAloneOverEveryFrameAndRepeat) {
    MAKE_SCENE_OR_FAIL(scene, "C:small");
    app::BenchPlan plan;
    plan.methods = {"brute", "aabb", "aabb-thesis"};
    plan.begin = 2;
    plan.end = 6;
    plan.repeat = 2;
    plan.threads = 2;
    plan.self_collision = scene.self_collision;
    int steps = 0;
    const app::BenchScene result = app::run_bench_scene(scene, plan, [&] { ++steps; });
    EXPECT_EQ(steps, 3 * 4 * 2);  // methods x frames x repeats, one progress step each
    EXPECT_TRUE(result.mismatches.empty());
    ASSERT_EQ(result.frames.size(), 3u * 4u);  // method-major, medians over the repeats
    for (std::size_t i = 0; i < result.frames.size(); ++i) {
        EXPECT_EQ(result.frames[i].method, plan.methods[i / 4]);
        EXPECT_EQ(result.frames[i].frame, plan.begin + i % 4);
    }
    // The same colliding pairs counted by every method on each frame, some on at least one.
    const std::size_t colliding = app::count_index("colliding_pairs");
    std::uint64_t total = 0;
    for (std::size_t i = 4; i < result.frames.size(); ++i) {
        EXPECT_EQ(result.frames[i].counts[colliding], result.frames[i % 4].counts[colliding]) << i;
    }
    for (std::size_t f = 0; f < 4; ++f) total += result.frames[f].counts[colliding];
    EXPECT_GT(total, 0u);
}

}  // namespace
}  // namespace collidescope
