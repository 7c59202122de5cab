// Bad input through the command line: exit code 2 and one line on stderr that names the file
// (never a crash, a hang or a second line), and usage errors.

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;
using testing_files::write_text;

constexpr const char* k_error_prefix = "collidescope: error: ";

// Runs `args` and expects exit 2 with exactly one stderr line, the error, mentioning `name`.
void expect_one_line_error(const std::vector<std::string>& args, const TempDir& dir, const std::string& name) {
    const testing::CliResult result = run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    const std::vector<std::string> lines = result.err_lines();
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_EQ(lines[0].rfind(k_error_prefix, 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(name), std::string::npos) << lines[0] << " does not name " << name;
    EXPECT_TRUE(result.out.empty()) << result.out;
}

std::string ascii_ply(const std::string& vertices, int vertex_count, const std::string& faces, int face_count) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertex_count) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(face_count) +
           "\nproperty list uchar int vertex_indices\nend_header\n" + vertices + faces;
}

constexpr const char* k_triangle_vertices = "0 0 0\n1 0 0\n0 1 0\n";

class CheckCliErrors : public ::testing::Test {
protected:
    void SetUp() override { write_ply(m_dir / "good.ply", testing::grid_sheet(2, 1.0)); }
    TempDir m_dir;
};

TEST_F(CheckCliErrors, MissingFile) { expect_one_line_error({"check", "good.ply", "missing.ply"}, m_dir, "missing.ply"); }

TEST_F(CheckCliErrors, TruncatedBinaryPly) {
    write_ply(m_dir / "whole.ply", testing::grid_sheet(4, 1.0));
    const std::string bytes = testing::read_text(m_dir / "whole.ply");
    write_text(m_dir / "cut.ply", bytes.substr(0, bytes.size() - 20));
    expect_one_line_error({"check", "good.ply", "cut.ply"}, m_dir, "cut.ply");
}

TEST_F(CheckCliErrors, TruncatedPlyHeader) {
    write_text(m_dir / "header.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nprop");
    expect_one_line_error({"check", "header.ply"}, m_dir, "header.ply");
}

TEST_F(CheckCliErrors, FaceIndexOutOfRange) {
    write_text(m_dir / "index.ply", ascii_ply(k_triangle_vertices, 3, "3 0 1 7\n", 1));
    expect_one_line_error({"check", "good.ply", "index.ply"}, m_dir, "index.ply");
}

TEST_F(CheckCliErrors, ObjFaceIndexOutOfRange) {
    write_text(m_dir / "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    expect_one_line_error({"check", "good.ply", "index.obj"}, m_dir, "index.obj");
}

TEST_F(CheckCliErrors, NanAndInfCoordinates) {
    write_text(m_dir / "nan.ply", ascii_ply("0 0 0\n1 nan 0\n0 1 0\n", 3, "3 0 1 2\n", 1));
    expect_one_line_error({"check", "good.ply", "nan.ply"}, m_dir, "nan.ply");
    write_text(m_dir / "inf.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n");
    expect_one_line_error({"check", "good.ply", "inf.obj"}, m_dir, "inf.obj");
}

TEST_F(CheckCliErrors, EmptyMesh) {
    write_text(m_dir / "empty.ply", ascii_ply(k_triangle_vertices, 3, "", 0));
    expect_one_line_error({"check", "good.ply", "empty.ply"}, m_dir, "empty.ply");
}

TEST_F(CheckCliErrors, DifferentFrameCounts) {
    for (int f = 0; f < 3; ++f) write_ply(m_dir / ("long." + std::to_string(f) + ".ply"), testing::grid_sheet(1, 1.0));
    for (int f = 0; f < 2; ++f) write_ply(m_dir / ("short." + std::to_string(f) + ".ply"), testing::grid_sheet(1, 1.0));
    expect_one_line_error({"check", "long.%d.ply", "short.%d.ply"}, m_dir, "short.%d.ply");
}

TEST_F(CheckCliErrors, PatternMatchingNothing) {
    expect_one_line_error({"check", "good.ply", "nothing.####.ply"}, m_dir, "nothing.####.ply");
}

TEST_F(CheckCliErrors, MalformedSceneJson) {
    write_text(m_dir / "broken.json", "{\"objects\": [ {\"pattern\": ");
    expect_one_line_error({"check", "broken.json"}, m_dir, "broken.json");
    write_text(m_dir / "wrong.json", "{\"objects\": 3}");
    expect_one_line_error({"check", "wrong.json"}, m_dir, "wrong.json");
    write_text(m_dir / "missing.json", "{\"objects\": [{\"pattern\": \"none.%04d.ply\"}]}");
    expect_one_line_error({"check", "missing.json"}, m_dir, "none.%04d.ply");
}

TEST_F(CheckCliErrors, BadFileInALaterFrameStopsThereNamingIt) {
    for (int f = 0; f < 4; ++f) write_ply(m_dir / ("seq." + std::to_string(f) + ".ply"), testing::grid_sheet(2, 1.0));
    write_text(m_dir / "seq.2.ply", ascii_ply(k_triangle_vertices, 3, "3 0 1 5\n", 1));
    const testing::CliResult result = run_cli({"check", "good.ply", "seq.%d.ply"}, m_dir.path());
    EXPECT_EQ(result.exit_code, 2);
    const std::vector<std::string> lines = result.err_lines();
    ASSERT_EQ(lines.size(), 4u) << result.err;  // scene, frame 0, frame 1, the error
    EXPECT_EQ(lines[2].rfind("frame 1: ", 0), 0u) << lines[2];
    EXPECT_EQ(lines[3].rfind(k_error_prefix, 0), 0u) << lines[3];
    EXPECT_NE(lines[3].find("seq.2.ply"), std::string::npos) << lines[3];
}

TEST_F(CheckCliErrors, UnwritableOutput) {
    expect_one_line_error({"check", "good.ply", "--pairs", "no/such/dir/pairs.tsv"}, m_dir, "no/such/dir/pairs.tsv");
}

TEST_F(CheckCliErrors, UsageErrorsExitTwo) {
    const std::vector<std::vector<std::string>> usages = {
        {},
        {"check"},
        {"check", "--no-such-option", "good.ply"},
        {"check", "--threads", "-1", "good.ply"},
        {"check", "--threads", "many", "good.ply"},
        {"check", "--method", "no-such-method", "good.ply"},
        {"check", "--self", "--no-self", "good.ply"},
        {"check", "--scene", "no-such-scene"},
        {"check", "--scene", "demo:no-such-preset"},
        {"check", "--scene", "demo", "good.ply"},
        {"check", "--pairs", "-", "--stats", "-", "good.ply"},
        {"no-such-command"},
    };
    for (const std::vector<std::string>& args : usages) {
        std::string joined;
        for (const std::string& arg : args) joined += arg + " ";
        SCOPED_TRACE(joined);
        const testing::CliResult result = run_cli(args, m_dir.path());
        EXPECT_EQ(result.exit_code, 2) << result.err;
        ASSERT_EQ(result.err_lines().size(), 1u) << result.err;
        EXPECT_EQ(result.err_lines()[0].rfind(k_error_prefix, 0), 0u) << result.err;
    }
}

TEST(CheckCliHelp, HelpAndVersionExitZero) {
    const TempDir dir;
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{{"--help"}, {"check", "--help"}, {"-h"}}) {
        const testing::CliResult result = run_cli(args, dir.path());
        EXPECT_EQ(result.exit_code, 0) << result.err;
        EXPECT_NE(result.out.find("Usage"), std::string::npos) << result.out;
    }
    const testing::CliResult check_help = run_cli({"check", "--help"}, dir.path());
    for (const char* documented : {"--frames", "half-open", "--pairs", "--stats", "--exit-zero", "Exit codes"}) {
        EXPECT_NE(check_help.out.find(documented), std::string::npos) << documented;
    }
    const testing::CliResult version = run_cli({"--version"}, dir.path());
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.out.rfind("collidescope ", 0), 0u) << version.out;
    EXPECT_NE(version.out.find("git"), std::string::npos) << version.out;
}

}  // namespace
}  // namespace collidescope
