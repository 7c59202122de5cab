// The fuzz targets' inputs, replayed by the gcc suite (docs/how-to/fuzzing.md): every file of the
// committed corpus through its target's entry (no exception but InputError may escape), and
// every past finding (tests/fuzz/regressions/<target>/) with the answer it must get now.

#include "entries.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace collidescope::fuzz {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path k_fuzz_dir = std::filesystem::path(COLLIDESCOPE_SOURCE_DIR) / "tests" / "fuzz";

// A committed input's bytes; recordings are committed gzipped (read_file_bytes unpacks .gz).
std::vector<std::byte> bytes_of(const std::filesystem::path& file) { return read_file_bytes(file); }

// A gzipped regression input unpacked to a file of its own, for the tests that open it by path.
class Unpacked {
public:
    explicit Unpacked(const std::filesystem::path& gz)
        : m_path(std::filesystem::temp_directory_path() /
                 (gz.stem().string() + "." + std::to_string(::getpid()))) {
        const std::vector<std::byte> bytes = read_file_bytes(gz);
        std::ofstream out(m_path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    }
    ~Unpacked() { std::filesystem::remove(m_path); }
    Unpacked(const Unpacked&) = delete;
    Unpacked& operator=(const Unpacked&) = delete;
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

std::string input_error(const auto& read) {
    try {
        read();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no InputError)";
}

class Corpus : public ::testing::TestWithParam<const char*> {};

// A finding fixed since would crash or hang here again (gcc has no sanitizers, but the hangs,
// uncaught exceptions and most wild reads show); the entries never throw but InputError.
TEST_P(Corpus, EveryInputReadsOrIsRejected) {
    const std::string target = GetParam();
    const Entry entry = entry_named(target);
    ASSERT_NE(entry, nullptr);
    std::size_t inputs = 0;
    std::size_t accepted = 0;
    for (const auto& file : std::filesystem::directory_iterator(k_fuzz_dir / "corpus" / target)) {
        SCOPED_TRACE(file.path().string());
        Outcome outcome = Outcome::Rejected;
        EXPECT_NO_THROW(outcome = entry(bytes_of(file.path())));
        accepted += outcome == Outcome::Accepted;
        ++inputs;
    }
    EXPECT_GT(inputs, 0u) << "no corpus for " << target;
    // The seeds are valid files: an entry that rejects them all reads nothing and would pass
    // any input without exercising the reader.
    EXPECT_GT(accepted, 0u) << "every corpus input of " << target << " was rejected";
}

INSTANTIATE_TEST_SUITE_P(Targets, Corpus, ::testing::Values("ply", "obj", "scene", "recording", "cache"));

// The seeds (tests/fuzz/make_seeds.py, run here with the built collidescope) are valid files
// of every form each reader takes: every one must read, or the corpus starts from broken files.
TEST(Seeds, ValidFilesAreAccepted) {
    const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                      ("collidescope_fuzz_seeds_" + std::to_string(::getpid()));
    const std::string command = "/usr/bin/python3 " + (k_fuzz_dir / "make_seeds.py").string() + " " + out.string() +
                                " " + COLLIDESCOPE_BIN + " >/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::size_t seeds = 0;
    for (const char* target : {"ply", "obj", "scene", "recording", "cache"}) {
        for (const auto& file : std::filesystem::directory_iterator(out / target)) {
            SCOPED_TRACE(file.path().string());
            EXPECT_EQ(entry_named(target)(bytes_of(file.path())), Outcome::Accepted);
            ++seeds;
        }
    }
    EXPECT_EQ(seeds, 5u + 2u + 5u + 4u + 2u);
    std::filesystem::remove_all(out);
}

std::filesystem::path regression(const std::string& name) { return k_fuzz_dir / "regressions" / name; }

// fuzz_ply, 96 s in: an element with no properties and a count of 6.6e16 made the ascii
// reader skip that many empty items (a hang). Its items take no text, so it reads at once;
// the file then fails on its own bad vertex data.
TEST(Regressions, PlyAsciiElementWithoutPropertiesDoesNotHang) {
    const std::filesystem::path file = regression("ply/ascii-element-without-properties.ply");
    EXPECT_EQ(read_ply(bytes_of(file)), Outcome::Rejected);
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement nothing 18446744073709551615\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const MeshData mesh = parse_ply(std::as_bytes(std::span(ply)), "empty.ply");
    EXPECT_EQ(mesh.triangles.size(), 1u);
}

// Made by hand from the aabb seed (h5py: /frames/decision/present = 1, mode[0] = 1e300):
// inspect converted the mode to int (undefined behaviour UBSan reported) and replay would too.
// The reader refuses a decision code that is no uint8.
TEST(Regressions, TraceDecisionCodeOutOfRangeIsAnInputError) {
    const std::filesystem::path gz = regression("recording/decision-mode-1e300.h5.gz");
    EXPECT_EQ(read_recording(bytes_of(gz)), Outcome::Rejected);
    const Unpacked file(gz);
    const recorder::Recording recording(file.path());
    EXPECT_THAT(input_error([&] { recording.frame_values("decision"); }),
                HasSubstr("/frames/decision/mode: frame row 0 holds 1e+300, not a code 0..255"));
}

// fuzz_recording, 11 inputs in: an object header moved by an inserted run of bytes fails its
// checksum; libhdf5 1.10.8 leaks a metadata cache block on that path (fuzz/lsan.supp). What
// our code must do: a clean InputError, and no HDF5 object left open (read_recording checks).
TEST(Regressions, TraceCorruptObjectHeaderIsAnInputError) {
    const std::filesystem::path gz = regression("recording/hdf5-header-leak.h5.gz");
    EXPECT_EQ(read_recording(bytes_of(gz)), Outcome::Rejected);
    const Unpacked file(gz);
    EXPECT_THAT(input_error([&] { recorder::Recording recording(file.path()); }),
                HasSubstr(file.path().string() + ": "));
}

}  // namespace
}  // namespace collidescope::fuzz
