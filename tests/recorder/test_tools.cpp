// inspect, validate and compare through the command line: bad files give one line naming the
// file and exit 2; validate catches hand-broken files (exit 1); compare finds a planted
// difference at its frame (exit 1) and nothing in identical pairs (exit 0).

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;
using testing_files::write_text;

class RecorderTools : public ::testing::Test {
protected:
    void SetUp() override {
        // brute: the method whose frames inspect counts below (the default is adaptive).
        const testing::CliResult result =
            run_cli({"record", "--scene", "demo:small", "--method", "brute", "-o", "run.h5", "-q"}, m_dir.path());
        ASSERT_EQ(result.exit_code, 0) << result.err;
    }
    // Copies run.h5 to `name` for breaking.
    std::filesystem::path copy(const std::string& name) {
        std::filesystem::copy_file(m_dir.path() / "run.h5", m_dir.path() / name);
        return m_dir.path() / name;
    }
    void expect_one_line_error(const std::vector<std::string>& args, const std::string& file) {
        const testing::CliResult result = run_cli(args, m_dir.path());
        EXPECT_EQ(result.exit_code, 2) << result.err;
        const auto lines = result.err_lines();
        ASSERT_EQ(lines.size(), 1u) << result.err;
        EXPECT_EQ(lines[0].rfind("collidescope: error: ", 0), 0u) << lines[0];
        EXPECT_NE(lines[0].find(file), std::string::npos) << lines[0];
    }
    // validate exits 1 with a problem line containing `expected`.
    void expect_invalid(const std::string& file, const std::string& expected) {
        const testing::CliResult result = run_cli({"validate", file}, m_dir.path());
        EXPECT_EQ(result.exit_code, 1) << result.err;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    }
    TempDir m_dir;
};

TEST_F(RecorderTools, InspectReportsWhatTheRecordingHolds) {
    const testing::CliResult text = run_cli({"inspect", "run.h5"}, m_dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("24 frames complete"), std::string::npos) << text.out;
    const testing::CliResult json_run = run_cli({"inspect", "--json", "run.h5"}, m_dir.path());
    ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
    const nlohmann::json info = nlohmann::json::parse(json_run.out);
    EXPECT_EQ(info["frames"], 24);
    EXPECT_EQ(info["finished"], true);
    EXPECT_EQ(info["methods"]["brute"], 24);
    EXPECT_EQ(info["method_switches"], 0);
    ASSERT_EQ(info["objects"].size(), 2u);
    const Scene scene = make_builtin_scene("demo:small");
    const Frame first = scene.source->frame(0);
    EXPECT_EQ(info["objects"][0]["topologies"][0]["triangles"], first.objects[0].triangle_count());
    const testing::CliResult checked = run_cli({"check", "--scene", "demo:small", "--pairs", "-", "--exit-zero", "-q"}, m_dir.path());
    EXPECT_EQ(info["pairs"]["total"], testing::parse_pairs_tsv(checked.out).size());
    EXPECT_TRUE(info["stages"].contains("total"));
    EXPECT_EQ(info["metadata"]["scene"], "demo");
    EXPECT_EQ(info["metadata"]["scene_preset"], "small");
}

TEST_F(RecorderTools, BadFilesGiveOneLineNamingTheFile) {
    write_text(m_dir.path() / "text.h5", "this is not HDF5\n");
    expect_one_line_error({"inspect", "text.h5"}, "text.h5");
    expect_one_line_error({"validate", "text.h5"}, "text.h5");
    expect_one_line_error({"compare", "run.h5", "text.h5"}, "text.h5");
    expect_one_line_error({"inspect", "missing.h5"}, "missing.h5");

    const std::string bytes = testing::read_text(m_dir.path() / "run.h5");
    write_text(m_dir.path() / "half.h5", bytes.substr(0, bytes.size() / 2));
    expect_one_line_error({"inspect", "half.h5"}, "half.h5");
    expect_one_line_error({"validate", "half.h5"}, "half.h5");

    // Garbage over the superblock and first object headers (after the 8-byte signature).
    std::string corrupt = bytes;
    for (std::size_t i = 8; i < 4096 && i < corrupt.size(); ++i) corrupt[i] = static_cast<char>(i * 7 + 3);
    write_text(m_dir.path() / "corrupt.h5", corrupt);
    expect_one_line_error({"inspect", "corrupt.h5"}, "corrupt.h5");

    testing::write_foreign_hdf5(m_dir.path() / "foreign.h5");
    expect_one_line_error({"inspect", "foreign.h5"}, "not a collidescope recording");
    expect_one_line_error({"validate", "foreign.h5"}, "foreign.h5");

    const auto newer = copy("newer.h5");
    testing::set_int_attr(newer, "/", recorder::schema::k_attr_version_major, 2);
    expect_one_line_error({"inspect", "newer.h5"}, "newer than this collidescope reads");
}

TEST_F(RecorderTools, ValidateAcceptsARecordingAndCatchesHandBrokenOnes) {
    EXPECT_EQ(run_cli({"validate", "run.h5"}, m_dir.path()).exit_code, 0);

    const auto offsets = copy("offsets.h5");
    testing::overwrite_u64(offsets, recorder::schema::k_pair_offsets, 12, 1u << 30);
    expect_invalid("offsets.h5", "out of range");

    const auto frames = copy("frames.h5");
    testing::overwrite_u64(frames, recorder::schema::k_frame_index, 5, 3);
    expect_invalid("frames.h5", "does not follow frame");

    const auto count = copy("count.h5");
    testing::overwrite_u64(count, std::string(recorder::schema::k_frame_counts) + "/colliding_pairs", 11, 7);
    expect_invalid("count.h5", "colliding_pairs");

    const auto unit = copy("unit.h5");
    testing::delete_attr(unit, "/frames/ms/narrow", recorder::schema::k_attr_unit);
    expect_invalid("unit.h5", "/frames/ms/narrow: no 'unit'");

    const auto unfinished = copy("unfinished.h5");
    testing::delete_attr(unfinished, "/", recorder::schema::k_attr_finished);
    expect_invalid("unfinished.h5", "not finished");
    EXPECT_EQ(run_cli({"validate", "--allow-incomplete", "unfinished.h5"}, m_dir.path()).exit_code, 0);
}

TEST_F(RecorderTools, CompareFindsAPlantedDifferenceAtItsFrame) {
    const Scene scene = make_builtin_scene("demo:small");
    std::filesystem::create_directories(m_dir.path() / "a");
    std::filesystem::create_directories(m_dir.path() / "b");
    const auto patterns_a = testing::write_scene_files(scene, m_dir.path() / "a");
    const auto patterns_b = testing::write_scene_files(scene, m_dir.path() / "b");
    // Plant: at frame 12 (where the scene collides) move object 1 far away in copy b.
    const std::filesystem::path planted = m_dir.path() / "b" / (scene.source->object_name(1) + ".0012.ply");
    write_ply(planted, testing::translated(read_mesh_file(planted), Vec3(100, 0, 0)));
    std::vector<std::string> args_a = {"record", "-q", "-o", "a.h5"}, args_b = {"record", "-q", "-o", "b.h5"};
    args_a.insert(args_a.end(), patterns_a.begin(), patterns_a.end());
    args_b.insert(args_b.end(), patterns_b.begin(), patterns_b.end());
    ASSERT_EQ(run_cli(args_a, m_dir.path()).exit_code, 0);
    ASSERT_EQ(run_cli(args_b, m_dir.path()).exit_code, 0);

    const testing::CliResult same = run_cli({"compare", "a.h5", "run.h5"}, m_dir.path());
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    EXPECT_NE(same.out.find("identical"), std::string::npos) << same.out;

    const testing::CliResult differ = run_cli({"compare", "a.h5", "b.h5"}, m_dir.path());
    EXPECT_EQ(differ.exit_code, 1) << differ.out << differ.err;
    EXPECT_NE(differ.out.find("first difference at frame 12;"), std::string::npos) << differ.out;
    EXPECT_NE(differ.out.find("1 frames differ"), std::string::npos) << differ.out;
    EXPECT_NE(differ.out.find("total"), std::string::npos) << differ.out;
}

// The budget sits between the fixed part of a demo:small recording (datasets, metadata, pairs
// and stats: about 150 KiB since schema 1.2 added the decision, hybrid, survivor and depth
// datasets) and the whole file (about 190 KiB), so positions must go for it to fit.
TEST_F(RecorderTools, BudgetDropsPositionsAndSaysSo) {
    const std::uint64_t whole = std::filesystem::file_size(m_dir.path() / "run.h5");
    const testing::CliResult run = run_cli({"record", "--scene", "demo:small", "-o", "budget.h5", "--budget", "175K"}, m_dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("dropped the vertex positions of"), std::string::npos) << run.err;
    EXPECT_LT(std::filesystem::file_size(m_dir.path() / "budget.h5"), whole);
    EXPECT_LE(std::filesystem::file_size(m_dir.path() / "budget.h5"), 175u * 1024);
    EXPECT_EQ(run_cli({"validate", "budget.h5"}, m_dir.path()).exit_code, 0);
    EXPECT_EQ(run_cli({"compare", "run.h5", "budget.h5"}, m_dir.path()).exit_code, 0) << "pairs are never dropped";
    const recorder::Recording rec(m_dir.path() / "budget.h5");
    std::uint64_t without = 0;
    for (std::uint64_t r = 0; r < rec.frames_complete(); ++r) without += rec.positions(0, r).empty() ? 1 : 0;
    EXPECT_GT(without, 0u);
    EXPECT_FALSE(rec.positions(0, 0).empty()) << "the first frame keeps its positions";
}

}  // namespace
}  // namespace collidescope
