// Animated model files through the command line: --fps / --clip, frames of the clip, and the
// bad inputs (exit 2, one line naming the file and the element).

#include "app/error_cases.hpp"
#include "mesh/temp_files.hpp"
#include "support/cli_runner.hpp"
#include "support/testmodels.hpp"
#include "support/tiny_rig.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace collidescope {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ErrorCase;
using testing::TinyRigOptions;
using testing_files::TempDir;

std::function<void(const fs::path&)> rig(const std::string& name, TinyRigOptions options = {}) {
    return [=](const fs::path& dir) { testing::write_tiny_rig(dir / name, options); };
}

TEST(AnimationCli, BadAnimatedInputsExitTwoWithOneLine) {
    REQUIRE_TESTMODEL(anim_test, "X/anim_test.x");
    const std::vector<ErrorCase> cases = {
        {"animated model: bone naming no node", nullptr, {"check", anim_test.string()},
         {anim_test.string(), "mesh 0 'pCylinder1' bone", "names no node"}},
        {"animated model: no such clip", rig("rig.assbin", {.second_clip = true}), {"check", "rig.assbin", "--clip", "walk"},
         {"rig.assbin", "no clip 'walk'", "0 'rise', 1 'idle'"}},
        {"animated model: clip index out of range", rig("rig.assbin"), {"check", "rig.assbin", "--clip", "3"},
         {"rig.assbin", "no clip '3'"}},
        {"animated model: NaN key", rig("nan.assbin", {.nan_key = true}), {"check", "nan.assbin"},
         {"nan.assbin", "clip 0 'rise' channel 0 'arm' position key 1", "not finite"}},
        {"animated model: zero weights everywhere", rig("zero.assbin", {.zero_weights = true}), {"record", "zero.assbin", "-o", "run.h5"},
         {"zero.assbin", "mesh 0: every bone weight is zero"}},
        {"animated model: --fps not positive", rig("rig.assbin"), {"check", "rig.assbin", "--fps", "0"}, {"--fps"}},
    };
    for (const ErrorCase& c : cases) {
        const TempDir dir;
        testing::expect_error_case(c, dir.path());
    }
}

TEST(AnimationCli, RecordOfABadRigWritesNothing) {
    const TempDir dir;
    testing::write_tiny_rig(dir / "zero.assbin", {.zero_weights = true});
    const testing::CliResult result = testing::run_cli({"record", "zero.assbin", "-o", "run.h5"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
}

TEST(AnimationCli, CheckSamplesTheClipAtFps) {
    const TempDir dir;
    testing::write_tiny_rig(dir / "rig.assbin", {.second_clip = true});
    const testing::CliResult result =
        testing::run_cli({"check", "rig.assbin", "--fps", "4", "--method", "brute", "--pairs", "pairs.tsv"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_THAT(result.err, HasSubstr("frames 0..4 of 5"));
    const testing::CliResult idle = testing::run_cli({"check", "rig.assbin", "--clip", "idle"}, dir.path());
    EXPECT_EQ(idle.exit_code, 0) << idle.err;
    EXPECT_THAT(idle.err, HasSubstr("of 16"));
}

}  // namespace
}  // namespace collidescope
