// `join --virtual`: the large row datasets of the output are HDF5 virtual datasets over the
// parts' rows. The output reads as the recording of the whole range (through the reader, the
// command line and plain h5py), also where part boundaries fall inside the positions chunks,
// from another current directory, after output and parts moved together and with the parts
// elsewhere under HDF5_VDS_PREFIX (the search HDF5 itself makes); a missing, short
// or unreadable part is an error naming it and the dataset, never zeros; a virtual output is
// refused as a part.

#include "join_helpers.hpp"
#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/join.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

namespace collidescope {
namespace {

namespace fs = std::filesystem;
using recorder::Recording;
using testing_files::TempDir;

recorder::JoinOptions virtual_join(std::uint64_t min_rows = 0) {
    recorder::JoinOptions options;
    options.layout = recorder::JoinLayout::Virtual;
    options.virtual_min_rows = min_rows;
    return options;
}

// Every object's positions at every complete row, element for element.
void expect_same_positions(const Recording& joined, const Recording& whole) {
    ASSERT_EQ(joined.frames_complete(), whole.frames_complete());
    for (std::uint32_t k = 0; k < whole.objects().size(); ++k) {
        for (std::uint64_t row = 0; row < whole.frames_complete(); ++row) {
            ASSERT_EQ(joined.positions(k, row), whole.positions(k, row)) << "object " << k << " row " << row;
        }
    }
}

// A scene whose vertex counts change after frame 0, recorded whole (whole.h5) and in parts
// part<i>.h5 at `bounds` inside `dir` / `parts_dir`.
std::vector<fs::path> record_parts(const Scene& scene, const std::vector<std::uint32_t>& bounds, const fs::path& dir,
                                   const fs::path& parts_dir) {
    fs::create_directories(parts_dir);
    testing::record_in_process(scene, dir / "whole.h5", bounds.front(), bounds.back(), false, "brute");
    std::vector<fs::path> parts;
    for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
        const fs::path part = parts_dir / ("part" + std::to_string(i) + ".h5");
        testing::record_in_process(scene, part, bounds[i], bounds[i + 1], false, "brute");
        parts.insert(parts.begin(), part);
    }
    return parts;
}

TEST(RecorderJoinVirtual, PartsWithMisalignedChunksEqualTheWholeRecording) {
    // Vertex counts above and below the first frame's (which sizes the positions chunks): the
    // copying join re-encodes here; the virtual join maps rows wherever they fall.
    for (const std::uint64_t seed : {25u, 26u, 27u}) {
        for (const std::uint64_t min_rows : {std::uint64_t{0}, std::uint64_t{40}}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + ", virtual_min_rows " + std::to_string(min_rows));
            TempDir dir;
            const std::vector<fs::path> parts =
                record_parts(testing::varying_vertex_counts(seed, 30), {0, 11, 12, 20, 30}, dir.path(), dir / "parts");
            const recorder::JoinSummary summary = recorder::join_recordings(parts, dir / "joined.h5", virtual_join(min_rows));
            EXPECT_GT(summary.virtual_datasets, 0u);
            if (min_rows == 0) {
                EXPECT_EQ(summary.raw_chunks, 0u) << "every chunked dataset is mapped, none copied";
            }
            const Recording joined(dir / "joined.h5"), whole(dir / "whole.h5");
            EXPECT_FALSE(joined.virtual_sources().empty());
            for (const recorder::VirtualSource& source : joined.virtual_sources()) {
                EXPECT_EQ(source.file.rfind("parts/part", 0), 0u) << source.file << " (relative to the output's directory)";
            }
            testing::expect_same_recording(joined, whole, true);
            expect_same_positions(joined, whole);
        }
    }
}

TEST(RecorderJoinVirtual, OnlyDatasetsOverTheThresholdAreMapped) {
    TempDir dir;
    const std::vector<fs::path> parts = record_parts(testing::varying_vertex_counts(25, 20), {0, 9, 20}, dir.path(), dir.path());
    const recorder::JoinSummary all = recorder::join_recordings(parts, dir / "all.h5", virtual_join(0));
    const recorder::JoinSummary none = recorder::join_recordings(parts, dir / "none.h5", virtual_join(1u << 30));
    EXPECT_EQ(none.virtual_datasets, 0u);
    EXPECT_TRUE(Recording(dir / "none.h5").virtual_sources().empty());
    const Recording mapped(dir / "all.h5");
    for (const recorder::VirtualSource& source : mapped.virtual_sources()) {
        // Offsets are rebased, so they are always copied.
        EXPECT_EQ(source.dataset.find("offsets"), std::string::npos) << source.dataset;
    }
    EXPECT_GT(all.virtual_datasets, 0u);
    const recorder::JoinSummary copied = recorder::join_recordings(parts, dir / "copy.h5");
    EXPECT_EQ(copied.virtual_datasets, 0u);
    testing::expect_same_recording(mapped, Recording(dir / "copy.h5"), true);
}

// Runs /usr/bin/python3 (Debian's, with h5py) on `code` with `args`, in `dir`; exit code and output.
std::pair<int, std::string> run_python(const std::string& code, const std::vector<std::string>& args, const fs::path& dir) {
    std::ofstream(dir / "check.py") << code;
    std::string command = "cd '" + dir.string() + "' && /usr/bin/python3 check.py";
    for (const std::string& arg : args) command += " '" + arg + "'";
    command += " > python.out 2>&1";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::read_text(dir / "python.out")};
}

// Plain h5py: every dataset but the measured times equal element for element, and the
// positions, triangles and pairs of the joined file virtual.
const char* const k_h5py_equal = R"(import sys, h5py, numpy as np
whole, joined = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
names = []
whole.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) and not n.startswith("frames/ms") else None)
virtual = []
for n in names:
    a, b = whole[n][()], joined[n][()]
    if a.shape != b.shape or not np.array_equal(a, b):
        sys.exit("differs: " + n)
    if joined[n].is_virtual:
        virtual.append(n)
assert any(n.endswith("positions") for n in virtual), virtual
print("equal:", len(names), "datasets;", "virtual:", " ".join(virtual))
)";

class VirtualJoinFiles : public ::testing::Test {
protected:
    // whole.h5, and run.h5 joined virtually from run.h5.parts/part<i>.h5 inside m_dir/a.
    void SetUp() override {
        m_parts = record_parts(testing::varying_vertex_counts(26, 24), {0, 7, 24}, m_dir / "a", m_dir / "a" / "run.h5.parts");
        const testing::CliResult join = testing::run_cli(
            {"join", "--virtual", "--virtual-min-rows", "0", "run.h5.parts/part1.h5", "run.h5.parts/part0.h5", "-o", "run.h5"},
            m_dir / "a");
        ASSERT_EQ(join.exit_code, 0) << join.err;
        EXPECT_NE(join.err.find("datasets virtual"), std::string::npos) << join.err;
        fs::create_directories(m_dir / "elsewhere");
    }

    // `args` run from m_dir/elsewhere: exit 2 and one line on stderr holding each of `named`.
    void expect_one_line_error(const std::vector<std::string>& args, const std::vector<std::string>& named) {
        const testing::CliResult result = testing::run_cli(args, m_dir / "elsewhere");
        EXPECT_EQ(result.exit_code, 2) << result.out << result.err;
        ASSERT_EQ(result.err_lines().size(), 1u) << result.err;
        for (const std::string& name : named) EXPECT_NE(result.err.find(name), std::string::npos) << result.err;
    }

    TempDir m_dir;
    std::vector<fs::path> m_parts;
};

TEST_F(VirtualJoinFiles, ReadsAsTheWholeRecordingFromAnyDirectoryAndAfterAMove) {
    for (const fs::path& at : {m_dir / "a", m_dir / "b"}) {
        SCOPED_TRACE(at.string());
        if (at != m_dir / "a") fs::rename(m_dir / "a", at);  // output and parts move together
        const std::string run = (at / "run.h5").string();
        const std::string moved_whole = (at / "whole.h5").string();
        const testing::CliResult compare = testing::run_cli({"compare", moved_whole, run}, m_dir / "elsewhere");
        EXPECT_EQ(compare.exit_code, 0) << compare.out << compare.err;
        const testing::CliResult validate = testing::run_cli({"validate", run}, m_dir / "elsewhere");
        EXPECT_EQ(validate.exit_code, 0) << validate.err;
        EXPECT_NE(validate.err.find("virtual join"), std::string::npos) << validate.err;
        EXPECT_NE(validate.err.find("run.h5.parts/part0.h5"), std::string::npos) << validate.err;
        testing::expect_same_recording(Recording(run), Recording(moved_whole), true);
        expect_same_positions(Recording(run), Recording(moved_whole));
        const auto [code, out] = run_python(k_h5py_equal, {moved_whole, run}, m_dir / "elsewhere");
        EXPECT_EQ(code, 0) << out;
    }
}

TEST_F(VirtualJoinFiles, AMissingPartIsAnErrorNamingItNeverZeros) {
    // A file of the same relative name under the current directory, where HDF5 itself would
    // look next: it must not stand in for the missing part.
    fs::create_directories(m_dir / "elsewhere" / "run.h5.parts");
    fs::copy_file(m_parts.front(), m_dir / "elsewhere" / "run.h5.parts" / "part1.h5");
    fs::remove(m_dir / "a" / "run.h5.parts" / "part1.h5");
    const std::string run = (m_dir / "a" / "run.h5").string();
    const std::vector<std::string> named = {"run.h5.parts/part1.h5", "missing", "maps rows of"};
    expect_one_line_error({"inspect", run}, named);
    expect_one_line_error({"validate", run}, named);
    expect_one_line_error({"compare", (m_dir / "a" / "whole.h5").string(), run}, named);
    expect_one_line_error({"replay", run, "-o", "frames"}, named);
    EXPECT_THROW(Recording{run}, InputError);
}

TEST_F(VirtualJoinFiles, PartsElsewhereAreFoundThroughHdf5VdsPrefixAsHdf5FindsThem) {
    // HDF5 searches HDF5_VDS_PREFIX before the file's own directory; the reader's check
    // follows the same search, so it checks the files HDF5 then reads.
    fs::create_directories(m_dir / "store");
    fs::rename(m_dir / "a" / "run.h5.parts", m_dir / "store" / "run.h5.parts");
    const fs::path run = m_dir / "a" / "run.h5";
    EXPECT_THROW(Recording{run}, InputError);
    setenv("HDF5_VDS_PREFIX", (m_dir / "store").c_str(), 1);
    try {
        const Recording joined(run), whole(m_dir / "a" / "whole.h5");
        EXPECT_EQ(joined.virtual_sources().front().resolved.rfind((m_dir / "store").string(), 0), 0u);
        testing::expect_same_recording(joined, whole, true);
        expect_same_positions(joined, whole);
    } catch (const InputError& error) {
        ADD_FAILURE() << error.what();
    }
    unsetenv("HDF5_VDS_PREFIX");
}

TEST_F(VirtualJoinFiles, AShortOrUnreadablePartIsAnErrorNamingIt) {
    const fs::path part = m_dir / "a" / "run.h5.parts" / "part1.h5";
    const std::string run = (m_dir / "a" / "run.h5").string();
    // Replaced by a shorter recording of the same scene: the mapping reads past its rows.
    testing::record_in_process(testing::varying_vertex_counts(26, 24), part, 7, 9, false, "brute");
    expect_one_line_error({"validate", run}, {"run.h5.parts/part1.h5", "rows"});
    { std::ofstream(part, std::ios::trunc) << "not HDF5\n"; }
    expect_one_line_error({"validate", run}, {"run.h5.parts/part1.h5", "unreadable"});
}

TEST_F(VirtualJoinFiles, AVirtualJoinIsRefusedAsAPart) {
    testing::record_in_process(testing::varying_vertex_counts(26, 30), m_dir / "a" / "late.h5", 24, 30, false, "brute");
    for (const char* layout : {"copy", "virtual"}) {
        SCOPED_TRACE(layout);
        std::vector<std::string> args = {"join", (m_dir / "a" / "run.h5").string(), (m_dir / "a" / "late.h5").string(), "-o",
                                         (m_dir / "a" / "again.h5").string()};
        if (std::string(layout) == "virtual") args.push_back("--virtual");
        expect_one_line_error(args, {"run.h5", "is a virtual join"});
        EXPECT_FALSE(fs::exists(m_dir / "a" / "again.h5"));
    }
}

}  // namespace
}  // namespace collidescope
