// Schema 1.1: the methods' own details reach the recording. A gpu run recorded and checked
// with --stats on the same frames (the engine is deterministic with its fixed seed): the
// per-frame GPU cull state and every pass, read back through h5py (check_details.py).

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

TEST(RecordingDetails, GpuCullStateAndPassesMatchTheStats) {
    TempDir dir;
    // Flags and fixed P: the cull's outcome does not depend on measured timings, so the two
    // runs make the same choices.
    const std::vector<std::string> gpu = {"--method", "gpu", "--gpu-cull", "flags", "--gpu-resolution", "64"};
    std::vector<std::string> record = {"record", "--scene", "D:small", "-o", "run.h5", "-q"};
    std::vector<std::string> check = {"check", "--scene", "D:small", "--stats", "stats.jsonl", "--exit-zero", "-q"};
    record.insert(record.end(), gpu.begin(), gpu.end());
    check.insert(check.end(), gpu.begin(), gpu.end());
    ASSERT_EQ(run_cli(record, dir.path()).exit_code, 0);
    ASSERT_EQ(run_cli(check, dir.path()).exit_code, 0);
    const std::string command = "/usr/bin/python3 '" COLLIDESCOPE_SOURCE_DIR "/tests/recorder/check_details.py' '" +
                                (dir.path() / "run.h5").string() + "' '" + (dir.path() / "stats.jsonl").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    const auto validate = run_cli({"validate", "run.h5"}, dir.path());
    EXPECT_EQ(validate.exit_code, 0) << validate.out << validate.err;
}

}  // namespace
}  // namespace collidescope
