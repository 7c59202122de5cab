// Random corruption: 32 random bytes written at a random offset of a finished recording, 1000
// times (seeded, printed; 200 in a sanitizer build). Reading and validating it must end with an
// outcome (0 the damage missed anything checked, 1 invalid, 2 unreadable: `validate`'s exit
// codes), never a crash. Schema 1.2 writes fixed-length string
// attributes because HDF5 1.10.8 could crash (1 run in 150) reading a corrupt variable-length
// string from the global heap, which has no checksum; and keeps links and attributes compact
// (in checksummed object headers), because 1.10.8 also crashed here (trial 60 of seed 6150)
// iterating a group whose dense link storage, a fractal heap without checksums, was corrupt.

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "support/sweep_size.hpp"
#include "app/error_cases.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/recorder/validate.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// What `collidescope validate` decides for a file (its exit code: 0 valid, 1 invalid, 2
// unreadable, which the command gives for any exception), in this process.
int validate_in_process(const std::filesystem::path& path) {
    try {
        const recorder::Recording recording(path);
        const recorder::ValidationReport report = recorder::validate_recording(recording);
        return report.problems.empty() && recording.partial_reason().empty() ? 0 : 1;
    } catch (const std::exception&) {
        return 2;
    }
}

TEST(RecorderCorruption, RandomBytesNeverCrashTheReader) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "-o", "run.h5", "-q"}, dir.path()).exit_code, 0);
    const std::string original = read_bytes(dir.path() / "run.h5");
    ASSERT_GT(original.size(), 4096u);
    constexpr unsigned k_seed = 6150;
    // Every trial reads and validates in this process (a crash fails the test binary), and
    // every 25th also runs `collidescope validate`, whose exit code must be the same outcome.
    // Starting the command for every trial took 80 s of the suite (0.08 s a start, most of it
    // the dynamic loader); in-process the 1,000 take a few seconds. A sanitizer build runs the
    // first 200 trials of the same sequence (support/sweep_size.hpp).
    constexpr int k_trials = testing::sweep_size(1000, 5);
    constexpr int k_command_every = 25;
    constexpr std::size_t k_bytes = 32;
    std::printf("corruption test: seed %u, %d trials of %zu random bytes (every %dth also by the command)\n", k_seed,
                k_trials, k_bytes, k_command_every);
    std::mt19937_64 rng(k_seed);
    std::uniform_int_distribution<std::size_t> offset_of(0, original.size() - k_bytes);
    std::uniform_int_distribution<int> byte(0, 255);
    int outcomes[3] = {0, 0, 0};
    for (int trial = 0; trial < k_trials; ++trial) {
        std::string bytes = original;
        const std::size_t offset = offset_of(rng);
        for (std::size_t i = 0; i < k_bytes; ++i) bytes[offset + i] = static_cast<char>(byte(rng));
        std::ofstream(dir.path() / "corrupt.h5", std::ios::binary | std::ios::trunc) << bytes;
        std::printf("corruption test: trial %d, offset %zu\n", trial, offset);  // the last one names a crash
        std::fflush(stdout);
        const int outcome = validate_in_process(dir.path() / "corrupt.h5");
        if (trial % k_command_every == 0) {
            const testing::CliResult result = run_cli({"validate", "corrupt.h5"}, dir.path());
            ASSERT_EQ(result.exit_code, outcome)
                << "seed " << k_seed << " trial " << trial << " offset " << offset << ": exit " << result.exit_code
                << " (in process: " << outcome << ")\n" << result.err;
        }
        ++outcomes[outcome];
    }
    std::printf("corruption test: %d valid, %d invalid, %d unreadable\n", outcomes[0], outcomes[1], outcomes[2]);
    EXPECT_GT(outcomes[1] + outcomes[2], 0) << "the damage is seen at least sometimes";
}

// Each class of bad recording through inspect, validate and replay: one line naming the file
// and the dataset or frame, exit 2 (unreadable) or, for validate, 1 (invalid).
TEST(RecorderCorruption, EachClassOfBadRecordingGetsOneLineNamingIt) {
    namespace fs = std::filesystem;
    namespace schema = recorder::schema;
    TempDir base;
    ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "-o", "run.h5", "-q"}, base.path()).exit_code, 0);
    const fs::path run = base.path() / "run.h5";
    const std::string whole = read_bytes(run);
    const auto copy_as = [&](const std::string& name, std::function<void(const fs::path&)> edit) {
        return [=](const fs::path& dir) {
            fs::copy_file(run, dir / name);
            if (edit) edit(dir / name);
        };
    };
    const auto bytes_as = [](const std::string& name, const std::string& bytes) {
        return [=](const fs::path& dir) { std::ofstream(dir / name, std::ios::binary) << bytes; };
    };
    const std::vector<testing::ErrorCase> cases = {
        {"recording: missing file", nullptr, {"inspect", "missing.h5"}, {"missing.h5", "no such file"}},
        {"recording: not HDF5", bytes_as("text.h5", "just text\n"), {"inspect", "text.h5"}, {"text.h5", "not an HDF5 file"}},
        {"recording: cut to half its size", bytes_as("cut.h5", whole.substr(0, whole.size() / 2)), {"inspect", "cut.h5"},
         {"cut.h5"}},
        {"recording: HDF5 but not a recording", [](const fs::path& d) { testing::write_foreign_hdf5(d / "foreign.h5"); },
         {"validate", "foreign.h5"}, {"foreign.h5", "not a collidescope recording"}},
        {"recording: newer schema major",
         copy_as("newer.h5", [](const fs::path& f) { testing::set_int_attr(f, "/", schema::k_attr_version_major, 2); }),
         {"inspect", "newer.h5"}, {"newer.h5", "2.", "newer than this collidescope reads"}},
        {"recording: a dataset missing",
         copy_as("missing_ds.h5", [](const fs::path& f) { testing::delete_link(f, "/objects/0/positions"); }),
         {"replay", "missing_ds.h5", "-o", "frames"}, {"missing_ds.h5", "missing dataset /objects/0/positions"}},
        {"recording: pair offsets out of range",
         copy_as("offsets.h5", [](const fs::path& f) { testing::overwrite_u64(f, schema::k_pair_offsets, 12, 1u << 30); }),
         {"validate", "-q", "offsets.h5"}, {"offsets.h5", schema::k_pair_offsets, "frame 11", "out of range"}, 1},
        {"recording: never finished (killed writer)",
         copy_as("unfinished.h5", [](const fs::path& f) { testing::delete_attr(f, "/", schema::k_attr_finished); }),
         {"validate", "-q", "unfinished.h5"}, {"unfinished.h5", "partial", "not finished", "frames complete"}, 1},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const fs::path dir = base.path() / ("case" + std::to_string(k));  // one TempDir per test
        fs::create_directories(dir);
        testing::expect_error_case(cases[k], dir);
    }
}

}  // namespace
}  // namespace collidescope
