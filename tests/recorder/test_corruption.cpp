// Random corruption: 32 random bytes written at a random offset of a finished recording, many
// times (seeded, printed). `validate` must end with an exit code (0 the damage missed anything
// checked, 1 invalid, 2 unreadable), never a crash. Schema 1.2 writes fixed-length string
// attributes because HDF5 1.10.8 could crash (1 run in 150) reading a corrupt variable-length
// string from the global heap, which has no checksum; and keeps links and attributes compact
// (in checksummed object headers), because 1.10.8 also crashed here (trial 60 of seed 6150)
// iterating a group whose dense link storage, a fractal heap without checksums, was corrupt.

#include "app/cli_runner.hpp"
#include "mesh/temp_files.hpp"

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

TEST(RecorderCorruption, RandomBytesNeverCrashTheReader) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "demo:small", "-o", "run.h5", "-q"}, dir.path()).exit_code, 0);
    const std::string original = read_bytes(dir.path() / "run.h5");
    ASSERT_GT(original.size(), 4096u);
    constexpr unsigned k_seed = 6150;
    constexpr int k_trials = 1000;
    constexpr std::size_t k_bytes = 32;
    std::printf("corruption test: seed %u, %d trials of %zu random bytes\n", k_seed, k_trials, k_bytes);
    std::mt19937_64 rng(k_seed);
    std::uniform_int_distribution<std::size_t> offset_of(0, original.size() - k_bytes);
    std::uniform_int_distribution<int> byte(0, 255);
    int outcomes[3] = {0, 0, 0};
    for (int trial = 0; trial < k_trials; ++trial) {
        std::string bytes = original;
        const std::size_t offset = offset_of(rng);
        for (std::size_t i = 0; i < k_bytes; ++i) bytes[offset + i] = static_cast<char>(byte(rng));
        std::ofstream(dir.path() / "corrupt.h5", std::ios::binary | std::ios::trunc) << bytes;
        const testing::CliResult result = run_cli({"validate", "corrupt.h5"}, dir.path());
        ASSERT_TRUE(result.exit_code >= 0 && result.exit_code <= 2)
            << "seed " << k_seed << " trial " << trial << " offset " << offset << ": exit " << result.exit_code
            << " (a crash)\n" << result.err;
        ++outcomes[result.exit_code];
    }
    std::printf("corruption test: %d valid, %d invalid, %d unreadable\n", outcomes[0], outcomes[1], outcomes[2]);
    EXPECT_GT(outcomes[1] + outcomes[2], 0) << "the damage is seen at least sometimes";
}

}  // namespace
}  // namespace collidescope
