// Numeric options say what they want in words (app/number_checks.hpp): `--fps 0` is one line,
// "must be a positive number of frames per second", not CLI11's range up to DBL_MAX; every
// numeric option of every subcommand refuses non-numbers, NaN, infinities and values out of
// range the same way, with exit code 2.

#include "number_checks.hpp"

#include "mesh/temp_files.hpp"
#include "support/cli_runner.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace collidescope {
namespace {

using app::non_negative_number;
using app::number_check_message;
using app::positive_number;
using app::whole_number;

TEST(NumberChecks, PositiveNumbers) {
    const CLI::Validator fps = positive_number("of frames per second");
    for (const char* good : {"30", "23.976", "1e-3", "0.5"}) EXPECT_EQ(number_check_message(fps, good), "") << good;
    EXPECT_EQ(number_check_message(fps, "0"), "must be a positive number of frames per second, not '0'");
    for (const char* bad : {"-1", "abc", "", "nan", "inf", "-inf", "1e999", "30fps", " 30"}) {
        EXPECT_EQ(number_check_message(fps, bad), std::string("must be a positive number of frames per second, not '") + bad + "'");
    }
}

TEST(NumberChecks, NonNegativeNumbers) {
    const CLI::Validator frames = non_negative_number("of frames");
    for (const char* good : {"0", "16", "2.5"}) EXPECT_EQ(number_check_message(frames, good), "") << good;
    for (const char* bad : {"-0.5", "x", "nan"}) {
        EXPECT_EQ(number_check_message(frames, bad), std::string("must be a number, 0 or more, of frames, not '") + bad + "'");
    }
}

TEST(NumberChecks, WholeNumbersInARange) {
    const CLI::Validator level = whole_number(0, 9, "(a gzip level)");
    for (const char* good : {"0", "4", "9"}) EXPECT_EQ(number_check_message(level, good), "") << good;
    for (const char* bad : {"10", "-1", "4.5", "four", "", "99999999999999999999"}) {
        EXPECT_EQ(number_check_message(level, bad), std::string("must be a whole number from 0 to 9 (a gzip level), not '") + bad + "'");
    }
}

struct BadValue {
    std::vector<std::string> args;
    std::string message;  ///< the whole stderr
};

// Every numeric option of the command line, as a user mistypes it.
TEST(NumberChecks, EveryNumericOptionSaysWhatItWants) {
    const testing_files::TempDir dir;
    ASSERT_EQ(testing::run_cli({"record", "--scene", "demo:small", "--frames", ":2", "-q", "-o", "r.h5"}, dir.path()).exit_code, 0);
    const std::vector<BadValue> cases = {
        {{"check", "--scene", "demo:small", "--fps", "0"},
         "collidescope: error: --fps: must be a positive number of frames per second, not '0' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--threads", "-1"},
         "collidescope: error: --threads: must be a whole number from 0 to 1024 of worker threads (0: all hardware threads), not '-1' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--rebuild-quality-limit", "nan"},
         "collidescope: error: --rebuild-quality-limit: must be a positive number (a multiple of the SAH cost right after a build), not 'nan' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--rebuild-payback-frames", "-2"},
         "collidescope: error: --rebuild-payback-frames: must be a number, 0 or more, of frames (0: the SAH cost alone decides), not '-2' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--rebuild-fraction", "0"},
         "collidescope: error: --rebuild-fraction: must be a positive number (a fraction of a rebuild's time), not '0' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--gpu-resolution", "0"},
         "collidescope: error: --gpu-resolution: must be a whole number from 1 to 8192 of pixels, not '0' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--triangles-per-query", "many"},
         "collidescope: error: --triangles-per-query: must be a whole number from 1 to 1048576 of triangles per query, not 'many' (see --help)\n"},
        {{"record", "--scene", "demo:small", "-o", "x.h5", "--compression", "10"},
         "collidescope: error: --compression: must be a whole number from 0 to 9 (a gzip level; 0: uncompressed), not '10' (see --help)\n"},
        {{"record", "--scene", "demo:small", "-o", "x.h5", "--writer-nice", "20"},
         "collidescope: error: --writer-nice: must be a whole number from 0 to 19 (a nice increment), not '20' (see --help)\n"},
        {{"check", "--scene", "demo:small", "--adaptive-seed", "-5"},
         "collidescope: error: --adaptive-seed: must be a whole number from 0 to 9223372036854775807 (a seed), not '-5' (see --help)\n"},
        {{"replay", "r.h5", "-o", "frames", "--threads", "abc"},
         "collidescope: error: --threads: must be a whole number from 0 to 1024 of render threads (0: all hardware threads), not 'abc' (see --help)\n"},
        {{"replay", "r.h5", "-o", "frames", "--sheet-count", "0"},
         "collidescope: error: --sheet-count: must be a whole number from 1 to 10000 of frames, not '0' (see --help)\n"},
        {{"compare", "r.h5", "r.h5", "--max-frames", "-1"},
         "collidescope: error: --max-frames: must be a whole number from 0 to 1000000 of frames, not '-1' (see --help)\n"},
        {{"join", "r.h5", "-o", "j.h5", "--virtual", "--virtual-min-rows", "-1"},
         "collidescope: error: --virtual-min-rows: must be a whole number from 0 to 1099511627776 of rows, not '-1' (see --help)\n"},
        {{"bench", "--scenes", "demo", "--repeat", "0"},
         "collidescope: error: --repeat: must be a whole number from 1 to 1000 of runs per method, not '0' (see --help)\n"},
    };
    for (const BadValue& bad : cases) {
        const testing::CliResult result = testing::run_cli(bad.args, dir.path());
        EXPECT_EQ(result.exit_code, 2) << bad.message;
        EXPECT_EQ(result.err, bad.message);
    }
    for (const char* left_out : {"x.h5", "frames", "j.h5"}) EXPECT_FALSE(std::filesystem::exists(dir.path() / left_out)) << left_out;
}

}  // namespace
}  // namespace collidescope
