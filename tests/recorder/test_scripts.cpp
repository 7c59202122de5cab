// The trace scripts in scripts/ (Debian's /usr/bin/python3 with h5py, numpy, matplotlib) on a
// small recording: pairs equal `check --pairs`, the plot is a PNG, the depth script says there
// are no depth buffers, compare finds a planted difference.

#include "recording_helpers.hpp"

#include "app/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

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
    const ScriptResult pairs = run_script("trace_pairs.py", {"run.h5"}, m_dir);
    ASSERT_EQ(pairs.exit_code, 0) << pairs.out;
    const testing::CliResult checked = run_cli({"check", "--scene", "demo:small", "--pairs", "-", "--exit-zero", "-q"}, m_dir.path());
    EXPECT_FALSE(checked.out.empty());
    EXPECT_EQ(pairs.out, checked.out);
    const ScriptResult summary = run_script("trace_pairs.py", {"run.h5", "--summary", "--frames", "11:12"}, m_dir);
    ASSERT_EQ(summary.exit_code, 0) << summary.out;
    EXPECT_EQ(summary.out.rfind("frame 11: ", 0), 0u) << summary.out;
}

TEST_F(TraceScripts, PlotWritesAPng) {
    const ScriptResult plot = run_script("trace_plot_times.py", {"run.h5", "-o", "times.png"}, m_dir);
    ASSERT_EQ(plot.exit_code, 0) << plot.out;
    const std::string png = testing::read_text(m_dir.path() / "times.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(TraceScripts, DepthSaysThereAreNone) {
    const ScriptResult depth = run_script("trace_depth.py", {"run.h5"}, m_dir);
    EXPECT_EQ(depth.exit_code, 0) << depth.out;
    EXPECT_NE(depth.out.find("no depth buffers in this recording"), std::string::npos) << depth.out;
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

    const ScriptResult same = run_script("trace_compare.py", {"run.h5", "run.h5"}, m_dir);
    EXPECT_EQ(same.exit_code, 0) << same.out;
    const ScriptResult differ = run_script("trace_compare.py", {"run.h5", "planted.h5"}, m_dir);
    EXPECT_EQ(differ.exit_code, 1) << differ.out;
    EXPECT_NE(differ.out.find("first difference at frame 13; 1 frames differ"), std::string::npos) << differ.out;
}

TEST_F(TraceScripts, RefuseAForeignFile) {
    testing::write_foreign_hdf5(m_dir.path() / "foreign.h5");
    const ScriptResult pairs = run_script("trace_pairs.py", {"foreign.h5"}, m_dir);
    EXPECT_NE(pairs.exit_code, 0);
    EXPECT_NE(pairs.out.find("not a collidescope recording"), std::string::npos) << pairs.out;
}

}  // namespace
}  // namespace collidescope
