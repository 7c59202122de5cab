// The child-process runner (support/cli_runner) fails a test whose child printed a sanitizer
// report, whatever its exit code, and the sanitizers exit with a code no command uses.

#include "mesh/temp_files.hpp"
#include "support/cli_runner.hpp"
#include "support/sanitizer_report.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace collidescope {
namespace {

using testing::k_sanitizer_exit_code;
using testing::sanitizer_report_line;

const std::string k_canary = COLLIDESCOPE_MEMORY_ERROR_CANARY;

// The canary run in a directory of its own (the runner keeps its output files there).
testing::CliResult run_canary(const char* mode) {
    const testing_files::TempDir dir;
    return testing::run_program(k_canary, {mode}, dir.path());
}

// Each runtime's report as gcc 12's libsanitizer prints it (abridged).
TEST(SanitizerReport, FindsTheFirstLineOfEachSanitizersReport) {
    EXPECT_EQ(sanitizer_report_line("frame 3: 12 pairs\n==77==ERROR: AddressSanitizer: heap-use-after-free on address 0x1\n"
                                    "SUMMARY: AddressSanitizer: heap-use-after-free a.cpp:3 in f\n"),
              "==77==ERROR: AddressSanitizer: heap-use-after-free on address 0x1");
    EXPECT_EQ(sanitizer_report_line("==9==ERROR: LeakSanitizer: detected memory leaks\n"),
              "==9==ERROR: LeakSanitizer: detected memory leaks");
    EXPECT_EQ(sanitizer_report_line("engine/src/bvh/build.cpp:40:17: runtime error: signed integer overflow: 1 + 2147483647\n"),
              "engine/src/bvh/build.cpp:40:17: runtime error: signed integer overflow: 1 + 2147483647");
    EXPECT_EQ(sanitizer_report_line("WARNING: ThreadSanitizer: data race (pid=5)\n"), "WARNING: ThreadSanitizer: data race (pid=5)");
    EXPECT_EQ(sanitizer_report_line("SUMMARY: UndefinedBehaviorSanitizer: undefined-behavior x.cpp:1:2 in"),
              "SUMMARY: UndefinedBehaviorSanitizer: undefined-behavior x.cpp:1:2 in");
}

TEST(SanitizerReport, OrdinaryErrorsAreNoReport) {
    EXPECT_EQ(sanitizer_report_line(""), "");
    EXPECT_EQ(sanitizer_report_line("collidescope: error: a.ply: vertex 3: NaN coordinate\n"), "");
    EXPECT_EQ(sanitizer_report_line("total: 40 frames, 12 with collisions, 1,204 pairs\n"), "");
}

TEST(SanitizerReport, AChildWithoutAReportPasses) {
    const auto clean = run_canary("clean");
    EXPECT_EQ(clean.exit_code, 0);
}

// A child that printed a report and exited 1, as the app does for "collisions found", fails the
// test although 1 is the exit code the test expects.
TEST(SanitizerReport, AReportFailsTheTestWhateverTheExitCode) {
    EXPECT_NONFATAL_FAILURE(
        {
            const auto result = run_canary("printed-report");
            EXPECT_EQ(result.exit_code, 1);
        },
        "a sanitizer report (exit code 1): ==4242==ERROR: AddressSanitizer: heap-buffer-overflow");
}

// The planted out-of-bounds read itself: in the address build ASan reports it and exits 86, and
// the runner fails the test; in other builds the read goes unseen (the report test above covers
// the runner there), and the child exits 1.
TEST(SanitizerReport, AChildsOutOfBoundsReadFailsTheTest) {
#if COLLIDESCOPE_SANITIZE_ADDRESS
    EXPECT_NONFATAL_FAILURE(
        {
            const auto result = run_canary("oob-read");
            EXPECT_EQ(result.exit_code, k_sanitizer_exit_code);
        },
        "ERROR: AddressSanitizer: heap-buffer-overflow");
#else
    const auto result = run_canary("oob-read");
    EXPECT_EQ(result.exit_code, 1);
#endif
}

#if COLLIDESCOPE_SANITIZE_ADDRESS
// UBSan and LSan exit with the same code in the address build.
TEST(SanitizerReport, UndefinedBehaviourAndLeaksExitWithTheSanitizersCode) {
    for (const char* mode : {"signed-overflow", "leak"}) {
        SCOPED_TRACE(mode);
        EXPECT_NONFATAL_FAILURE(
            {
                const auto result = run_canary(mode);
                EXPECT_EQ(result.exit_code, k_sanitizer_exit_code);
            },
            "a sanitizer report (exit code 86)");
    }
}
#endif

}  // namespace
}  // namespace collidescope
