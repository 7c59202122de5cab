// --budget with depth images: they go first (every 2nd, 4th, ... frame that has them, then all),
// and only then positions; the summary line says what went; pairs never go.

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

class DepthBudget : public ::testing::Test {
protected:
    // C:small through the GPU cull at 64 x 64, depth images on every frame (3 views a frame).
    std::vector<std::string> record_args(const std::string& output, const std::string& depth) const {
        return {"record", "--scene", "C:small", "--method", "gpu", "--gpu-resolution", "64", "--depth", depth,
                "-o", output};
    }
    void SetUp() override {
        ASSERT_EQ(run_cli(record_args("whole.h5", "every:1"), m_dir.path()).exit_code, 0);
        ASSERT_EQ(run_cli(record_args("plain.h5", "off"), m_dir.path()).exit_code, 0);
        m_whole = std::filesystem::file_size(m_dir.path() / "whole.h5");
        m_plain = std::filesystem::file_size(m_dir.path() / "plain.h5");
        ASSERT_GT(m_whole, m_plain + m_plain / 4) << "depth images are a good part of the file";
    }
    testing::CliResult record_within(std::uint64_t budget) {
        std::vector<std::string> args = record_args("budget.h5", "every:1");
        args.push_back("--budget");
        args.push_back(std::to_string(budget));
        return run_cli(args, m_dir.path());
    }
    std::uint64_t budget_file_size() const { return std::filesystem::file_size(m_dir.path() / "budget.h5"); }

    TempDir m_dir;
    std::uint64_t m_whole = 0;
    std::uint64_t m_plain = 0;
};

TEST_F(DepthBudget, DepthImagesGoFirst) {
    const std::uint64_t budget = (m_plain + m_whole) / 2;
    const testing::CliResult run = record_within(budget);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("dropped the depth images of"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("vertex positions"), std::string::npos) << run.err;
    EXPECT_LE(budget_file_size(), budget);
    const recorder::Recording rec(m_dir.path() / "budget.h5");
    std::uint64_t with_depth = 0;
    for (std::uint64_t r = 0; r < rec.frames_complete(); ++r) {
        EXPECT_FALSE(rec.positions(0, r).empty()) << "row " << r << ": positions kept while depth images go";
        with_depth += rec.depth_images(r).empty() ? 0 : 1;
    }
    EXPECT_FALSE(rec.depth_images(0).empty()) << "the first frame keeps its depth images";
    EXPECT_GT(with_depth, 0u);
    EXPECT_LT(with_depth, rec.frames_complete());
}

TEST_F(DepthBudget, ThenPositions) {
    const std::uint64_t budget = m_plain * 9 / 10;
    const testing::CliResult run = record_within(budget);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("dropped the depth images of"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(", then the vertex positions of"), std::string::npos) << run.err;
    EXPECT_LE(budget_file_size(), budget);
    EXPECT_EQ(run_cli({"validate", "budget.h5"}, m_dir.path()).exit_code, 0);
    EXPECT_EQ(run_cli({"compare", "whole.h5", "budget.h5"}, m_dir.path()).exit_code, 0) << "pairs are never dropped";
    const recorder::Recording rec(m_dir.path() / "budget.h5");
    std::uint64_t without_positions = 0;
    for (std::uint64_t r = 0; r < rec.frames_complete(); ++r) {
        without_positions += rec.positions(0, r).empty() ? 1 : 0;
        // Positions only go once no depth image is kept any more.
        if (rec.positions(0, r).empty()) {
            EXPECT_TRUE(rec.depth_images(r).empty()) << "row " << r;
        }
    }
    EXPECT_GT(without_positions, 0u);
}

}  // namespace
}  // namespace collidescope
