// The recording scripts in scripts/ (Debian's /usr/bin/python3 with h5py, numpy, matplotlib) on a
// small recording: pairs equal `check --pairs`, the plot is a PNG, the depth script says there
// are no depth buffers, compare finds a planted difference.

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

struct ScriptResult {
    int exit_code = -1;
    std::string out;
};

ScriptResult run_script(const std::string& script, const std::vector<std::string>& args, const TempDir& dir) {
    std::string command = "cd '" + dir.path().string() + "' && MPLBACKEND=Agg /usr/bin/python3 '" +
                          std::string(COLLIDESCOPE_SOURCE_DIR) + "/scripts/" + script + "'";
    for (const std::string& arg : args) command += " '" + arg + "'";
    command += " > script.out 2>&1";
    const int status = std::system(command.c_str());
    ScriptResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = testing::read_text(dir.path() / "script.out");
    return result;
}

class TraceScripts : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "-o", "run.h5", "-q"}, m_dir.path()).exit_code, 0);
    }
    TempDir m_dir;
};

TEST_F(TraceScripts, PairsEqualCheck) {
    const ScriptResult pairs = run_script("recording_pairs.py", {"run.h5"}, m_dir);
    ASSERT_EQ(pairs.exit_code, 0) << pairs.out;
    const testing::CliResult checked = run_cli({"check", "--scene", "demo:small", "--pairs", "-", "--exit-zero", "-q"}, m_dir.path());
    EXPECT_FALSE(checked.out.empty());
    EXPECT_EQ(pairs.out, checked.out);
    const ScriptResult summary = run_script("recording_pairs.py", {"run.h5", "--summary", "--frames", "11:12"}, m_dir);
    ASSERT_EQ(summary.exit_code, 0) << summary.out;
    EXPECT_EQ(summary.out.rfind("frame 11: ", 0), 0u) << summary.out;
}

TEST_F(TraceScripts, PlotWritesAPng) {
    const ScriptResult plot = run_script("recording_plot_times.py", {"run.h5", "-o", "times.png"}, m_dir);
    ASSERT_EQ(plot.exit_code, 0) << plot.out;
    const std::string png = testing::read_text(m_dir.path() / "times.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(TraceScripts, DepthSaysThereAreNone) {
    const ScriptResult depth = run_script("recording_depth.py", {"run.h5"}, m_dir);
    EXPECT_EQ(depth.exit_code, 0) << depth.out;
    EXPECT_NE(depth.out.find("no depth buffers in this recording"), std::string::npos) << depth.out;
}

// A recording with depth images: the script draws one (a PNG with a colour bar) and names it.
TEST_F(TraceScripts, DepthDrawsARecordedImage) {
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--method", "gpu", "--gpu-resolution", "64", "--depth", "every:4",
                       "--frames", "0:5", "-o", "depth.h5", "-q"},
                      m_dir.path())
                  .exit_code,
              0);
    const ScriptResult depth = run_script("recording_depth.py", {"depth.h5", "--frame", "4", "-o", "depth.png"}, m_dir);
    ASSERT_EQ(depth.exit_code, 0) << depth.out;
    EXPECT_NE(depth.out.find("frame 4, image 0"), std::string::npos) << depth.out;
    EXPECT_NE(depth.out.find("input length unit"), std::string::npos) << depth.out;
    const std::string png = testing::read_text(m_dir.path() / "depth.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    const ScriptResult none = run_script("recording_depth.py", {"depth.h5", "--frame", "1"}, m_dir);
    EXPECT_EQ(none.exit_code, 1) << "frame 1 has no depth image: " << none.out;
}

// An adaptive recording: inspect reports the decision system's modes and switches.
TEST_F(TraceScripts, InspectReportsModesOfTheDecisionSystem) {
    ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "--method", "adaptive", "-o", "adaptive.h5", "-q"}, m_dir.path())
                  .exit_code,
              0);
    const testing::CliResult inspect = run_cli({"inspect", "--json", "adaptive.h5"}, m_dir.path());
    ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
    const nlohmann::json info = nlohmann::json::parse(inspect.out);
    EXPECT_EQ(info["decision_frames"], info["frames"]);
    std::uint64_t frames = 0;
    for (const auto& [mode, count] : info["modes"].items()) frames += count.get<std::uint64_t>();
    EXPECT_EQ(frames, info["frames"].get<std::uint64_t>());
    EXPECT_TRUE(info.contains("mode_switches"));
    ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "--method", "brute", "-o", "brute.h5", "-q"}, m_dir.path()).exit_code, 0);
    const testing::CliResult brute = run_cli({"inspect", "--json", "brute.h5"}, m_dir.path());
    ASSERT_EQ(brute.exit_code, 0);
    EXPECT_EQ(nlohmann::json::parse(brute.out)["decision_frames"], 0) << "no decision system: no modes";
}

TEST_F(TraceScripts, CompareFindsAPlantedDifference) {
    const Scene scene = make_builtin_scene("demo:small");
    const auto patterns = testing::write_scene_files(scene, m_dir.path());
    // Object 1 far away at frame 13 only (the scene collides there).
    const std::filesystem::path planted = m_dir.path() / (scene.source->object_name(1) + ".0013.ply");
    write_ply(planted, testing::translated(read_mesh_file(planted), Vec3(0, 0, 50)));
    std::vector<std::string> args = {"record", "-q", "-o", "planted.h5"};
    args.insert(args.end(), patterns.begin(), patterns.end());
    ASSERT_EQ(run_cli(args, m_dir.path()).exit_code, 0);

    const ScriptResult same = run_script("recording_compare.py", {"run.h5", "run.h5"}, m_dir);
    EXPECT_EQ(same.exit_code, 0) << same.out;
    const ScriptResult differ = run_script("recording_compare.py", {"run.h5", "planted.h5"}, m_dir);
    EXPECT_EQ(differ.exit_code, 1) << differ.out;
    EXPECT_NE(differ.out.find("first difference at frame 13; 1 frames differ"), std::string::npos) << differ.out;
}

TEST_F(TraceScripts, RefuseAForeignFile) {
    testing::write_foreign_hdf5(m_dir.path() / "foreign.h5");
    const ScriptResult pairs = run_script("recording_pairs.py", {"foreign.h5"}, m_dir);
    EXPECT_NE(pairs.exit_code, 0);
    EXPECT_NE(pairs.out.find("not a collidescope recording"), std::string::npos) << pairs.out;
}

}  // namespace
}  // namespace collidescope
