// Frame-parallel runs under mpirun (app/ranks/ranks.hpp, docs/how-to/mpi.md): the blocks of frames each rank
// takes; `check` on 2 and 3 ranks (oversubscribed) gives the serial run's pairs TSV byte for
// byte, its stats in frame order and its exit code, for every method; `record` on 2 ranks gives
// a recording that `compare` finds equal to the serial one, joined virtually over the parts it
// keeps in FILE.parts/ by default and copied into one file with `--join copy`; a bad frame in one block and a rank
// killed with SIGKILL end the run with an error naming the rank, and every finished frame stays
// readable (`join --allow-incomplete`, `validate --allow-incomplete`).
//
// Open MPI refuses to run as root (CI does) unless told: the tests set its two variables. Under
// CI=true a build without Open MPI, or no mpirun, fails these tests instead of skipping them.

#include "ranks/ranks.hpp"

#include "mpi_run.hpp"

#include "support/cli_runner.hpp"
#include "support/sweep_size.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>


namespace collidescope {
namespace {

namespace fs = std::filesystem;
using app::FrameRange;
using testing::CliResult;
using testing_files::TempDir;

TEST(FrameBlocks, ContiguousInRankOrderSizesWithinOne) {
    for (std::uint32_t begin : {0u, 3u, 100u}) {
        for (std::uint32_t frames = 1; frames <= 40; ++frames) {
            for (int size = 1; size <= static_cast<int>(std::min<std::uint32_t>(frames, 9)); ++size) {
                std::uint32_t next = begin, smallest = frames, largest = 0;
                for (int rank = 0; rank < size; ++rank) {
                    const FrameRange block = app::ranks::block_of({begin, begin + frames}, rank, size);
                    ASSERT_EQ(block.begin, next) << frames << " frames, rank " << rank << " of " << size;
                    ASSERT_GT(block.end, block.begin);
                    smallest = std::min(smallest, block.end - block.begin);
                    largest = std::max(largest, block.end - block.begin);
                    next = block.end;
                }
                EXPECT_EQ(next, begin + frames);
                EXPECT_LE(largest - smallest, 1u);
            }
        }
    }
}

TEST(FrameBlocks, MoreRanksThanFramesIsAnError) {
    EXPECT_THROW(app::ranks::block_of({0, 3}, 0, 4), InputError);
    EXPECT_NO_THROW(app::ranks::block_of({0, 4}, 3, 4));
}

using testing_mpi::frames_complete_now;
using testing_mpi::mpirun_command;
using testing_mpi::quoted;
using testing_mpi::run_mpi;
using testing_mpi::with;

// (frame, colliding_pairs) of each stats line, in the file's order.
std::vector<std::pair<long, long>> stats_frames(const std::string& jsonl) {
    std::vector<std::pair<long, long>> frames;
    std::istringstream in(jsonl);
    for (std::string line; std::getline(in, line);) {
        const auto frame = line.find("\"frame\":");
        const auto pairs = line.find("\"colliding_pairs\":");
        EXPECT_NE(frame, std::string::npos) << line;
        EXPECT_NE(pairs, std::string::npos) << line;
        if (frame == std::string::npos || pairs == std::string::npos) continue;
        frames.emplace_back(std::stol(line.substr(frame + 8)), std::stol(line.substr(pairs + 18)));
    }
    return frames;
}

struct SceneMethods {
    std::string scene;
    std::string frames;
    std::vector<std::string> methods;
};

// Each kind of method on small built-in scenes: every decision rule (they carry state from frame
// to frame, which a rank starting mid-run must not), the trees, brute force, the hybrid and the
// GPU cull (llvmpipe here, on fewer frames). Not every method on every scene: each case starts
// mpirun twice, some 1.3 s each here and several times that under the sanitizers.
const std::vector<SceneMethods> k_cases = {
    {"C:small", ":12", {"aabb", "adaptive", "adaptive-thesis", "adaptive-cost"}},
    {"C:small", ":6", {"gpu"}},
    {"D:small", ":9", {"brute", "adaptive"}},
    {"demo", ":9", {"hybrid"}},
};

TEST(MpiCheck, TwoAndThreeRanksGiveTheSerialPairsStatsAndExitCode) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    for (const SceneMethods& c : k_cases) {
        // A sanitizer build runs each scene's first method (the stateful rules' hand-over between
        // ranks is the normal build's to check; every kind of frame split runs in both).
        for (const std::string& method : testing::sweep_of(c.methods, 4)) {
            SCOPED_TRACE(c.scene + " --frames " + c.frames + " --method " + method);
            const std::vector<std::string> check = {"check", "--scene", c.scene, "--frames", c.frames, "--method", method,
                                                    "--threads", "1", "-q", "--stats", "stats.jsonl"};
            const CliResult serial = testing::run_cli(with(check, {"--pairs", "serial.tsv"}), dir.path());
            ASSERT_TRUE(serial.exit_code == 0 || serial.exit_code == 1) << serial.err;
            const std::string serial_pairs = testing::read_text(dir / "serial.tsv");
            const auto serial_stats = stats_frames(testing::read_text(dir / "stats.jsonl"));
            // Three ranks (an uneven split, the pairs to stdout) once, on the first case.
            const std::vector<int> rank_counts = &c == &k_cases.front() && method == c.methods.front() ? std::vector<int>{2, 3} : std::vector<int>{2};
            for (const int ranks : rank_counts) {
                SCOPED_TRACE(std::to_string(ranks) + " ranks");
                // Two ranks write the pairs to a file, three to stdout.
                const bool to_stdout = ranks == 3;
                const CliResult parallel = run_mpi(ranks, with(check, {"--pairs", to_stdout ? "-" : "mpi.tsv"}), dir.path());
                EXPECT_EQ(parallel.exit_code, serial.exit_code) << parallel.err;
                EXPECT_EQ(to_stdout ? parallel.out : testing::read_text(dir / "mpi.tsv"), serial_pairs);
                EXPECT_EQ(stats_frames(testing::read_text(dir / "stats.jsonl")), serial_stats);
                EXPECT_FALSE(fs::exists(dir / "stats.jsonl.partial"));
            }
        }
    }
}

// `file` reads as `serial`: compare exit 0, valid, the same datasets and rows, the same
// positions element for element (plain h5py included).
void expect_serial_recording(const fs::path& dir, const std::string& file) {
    const CliResult compare = testing::run_cli({"compare", "serial.h5", file}, dir);
    EXPECT_EQ(compare.exit_code, 0) << compare.out;
    EXPECT_EQ(testing::run_cli({"validate", file}, dir).exit_code, 0);
    const recorder::Recording serial(dir / "serial.h5"), joined(dir / file);
    EXPECT_EQ(joined.dataset_paths(), serial.dataset_paths());
    for (const std::string& path : serial.dataset_paths()) EXPECT_EQ(joined.rows_of(path), serial.rows_of(path)) << path;
    for (std::uint32_t k = 0; k < serial.objects().size(); ++k) {
        for (std::uint64_t row = 0; row < serial.frames_complete(); ++row) {
            ASSERT_EQ(joined.positions(k, row), serial.positions(k, row)) << file << " object " << k << " row " << row;
        }
    }
    const std::string h5py = "cd " + quoted(dir.string()) +
                             " && /usr/bin/python3 -c 'import sys, h5py, numpy as np; a, b = h5py.File(\"serial.h5\", \"r\"), "
                             "h5py.File(sys.argv[1], \"r\"); sys.exit(0 if all(np.array_equal(a[n][()], b[n][()]) for n in "
                             "(\"objects/0/positions\", \"objects/1/positions\", \"collisions/pairs\")) else 1)' " +
                             quoted(file);
    EXPECT_EQ(std::system(h5py.c_str()), 0) << "h5py: positions or pairs of " << file << " differ from serial.h5";
}

TEST(MpiRecord, TwoRanksJoinVirtuallyByDefaultAndCopyOnRequest) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    const std::vector<std::string> record = {"record", "--scene", "D:small", "--method", "aabb", "--threads", "1", "-q"};
    ASSERT_EQ(testing::run_cli(with(record, {"-o", "serial.h5"}), dir.path()).exit_code, 0);

    const CliResult virtual_join = run_mpi(2, with(record, {"-o", "mpi.h5"}), dir.path());
    ASSERT_EQ(virtual_join.exit_code, 0) << virtual_join.err;
    EXPECT_NE(virtual_join.err.find("joined the 2 ranks' parts"), std::string::npos) << virtual_join.err;
    EXPECT_NE(virtual_join.err.find("mpi.h5.parts/"), std::string::npos) << virtual_join.err;
    // The parts are the data: kept.
    EXPECT_TRUE(fs::exists(dir / "mpi.h5.parts" / "rank0.h5"));
    EXPECT_TRUE(fs::exists(dir / "mpi.h5.parts" / "rank1.h5"));
    EXPECT_FALSE(recorder::Recording(dir / "mpi.h5").virtual_sources().empty());
    expect_serial_recording(dir.path(), "mpi.h5");

    const CliResult copy_join = run_mpi(2, with(record, {"--join", "copy", "-o", "copy.h5"}), dir.path());
    ASSERT_EQ(copy_join.exit_code, 0) << copy_join.err;
    EXPECT_FALSE(fs::exists(dir / "copy.h5.rank0.h5"));
    EXPECT_FALSE(fs::exists(dir / "copy.h5.rank1.h5"));
    EXPECT_FALSE(fs::exists(dir / "copy.h5.parts"));
    EXPECT_TRUE(recorder::Recording(dir / "copy.h5").virtual_sources().empty());
    expect_serial_recording(dir.path(), "copy.h5");
}

TEST(MpiFaults, BadFrameInOneBlockNamesRankAndFrameAndKeepsFinishedFrames) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    ASSERT_EQ(testing::run_cli({"export", "C:small", "--frames", ":16", "-o", "scene", "-q"}, dir.path()).exit_code, 0);
    const std::vector<std::string> check = {"check", "scene/scene.json", "--method", "aabb", "--threads", "1", "-q"};
    ASSERT_EQ(testing::run_cli(with(check, {"--exit-zero", "--pairs", "serial.tsv"}), dir.path()).exit_code, 0);
    { std::ofstream(dir / "scene" / "sheet_0.0011.ply") << "not a mesh\n"; }  // rank 1 of 2 takes frames 8..15

    const CliResult checked = run_mpi(2, with(check, {"--pairs", "mpi.tsv"}), dir.path());
    EXPECT_EQ(checked.exit_code, 2) << checked.err;
    const std::string line = "collidescope: error: rank 1 of 2, frames 8..15, at frame 11: scene/sheet_0.0011.ply";
    EXPECT_NE(checked.err.find(line), std::string::npos) << checked.err;
    // Frames 0..10 were finished (rank 1 got to 10): the partial output holds exactly them.
    EXPECT_FALSE(fs::exists(dir / "mpi.tsv"));
    std::vector<testing::FramePair> expected;
    for (const testing::FramePair& p : testing::parse_pairs_tsv(testing::read_text(dir / "serial.tsv"))) {
        if (p.frame < 11) expected.push_back(p);
    }
    EXPECT_EQ(testing::parse_pairs_tsv(testing::read_text(dir / "mpi.tsv.partial")), expected);

    const CliResult recorded = run_mpi(2, {"record", "scene/scene.json", "--method", "aabb", "--threads", "1", "-q", "-o", "run.h5"},
                                       dir.path());
    EXPECT_EQ(recorded.exit_code, 2) << recorded.err;
    EXPECT_NE(recorded.err.find(line), std::string::npos) << recorded.err;
    EXPECT_NE(recorded.err.find("join --allow-incomplete"), std::string::npos) << recorded.err;
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
    const CliResult joined = testing::run_cli(
        {"join", "--allow-incomplete", "run.h5.parts/rank0.h5", "run.h5.parts/rank1.h5", "-o", "kept.h5"}, dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.err;
    EXPECT_EQ(testing::run_cli({"validate", "--allow-incomplete", "kept.h5"}, dir.path()).exit_code, 0);
    const recorder::Recording kept(dir / "kept.h5");
    EXPECT_EQ(kept.frames_complete(), 11u);
    for (std::uint64_t r = 0; r < kept.frames_complete(); ++r) {
        std::vector<TrianglePair> pairs;
        for (const testing::FramePair& p : expected) {
            if (p.frame == r) pairs.push_back(p.pair);
        }
        EXPECT_EQ(kept.pairs(r), pairs) << "frame " << r;
    }
}


// The pid of the process whose environment holds both `tag` and OMPI_COMM_WORLD_RANK=`rank`.
pid_t find_rank(const std::string& tag, int rank) {
    const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
    for (const fs::directory_entry& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream in(entry.path() / "environ", std::ios::binary);
        const std::string environment((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::vector<std::string> variables;
        std::istringstream split(environment);
        for (std::string v; std::getline(split, v, '\0');) variables.push_back(v);
        const bool tagged = std::find(variables.begin(), variables.end(), tag) != variables.end();
        const bool ranked = std::find(variables.begin(), variables.end(), want) != variables.end();
        if (tagged && ranked) return static_cast<pid_t>(std::stol(name));
    }
    return -1;
}

TEST(MpiFaults, SigkillOfARankEndsTheRunNamingItAndKeepsEveryFinishedFrame) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    // C's first 60 frames on AABB trees, one thread: about 60 ms a frame, 2 s per rank.
    const std::string tag = "COLLIDESCOPE_TEST_JOB=" + std::to_string(getpid());
    const std::string command = "export " + tag + " && " +
                                mpirun_command(2, {"record", "--scene", "C", "--frames", ":60", "--method", "aabb", "--threads",
                                                   "1", "-q", "-o", "run.h5"},
                                               dir.path());
    const pid_t mpirun = testing_mpi::spawn_shell(command);
    ASSERT_GT(mpirun, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    bool killed = false;
    while (!killed && std::chrono::steady_clock::now() < deadline) {
        if (waitpid(mpirun, nullptr, WNOHANG) == mpirun) break;
        if (frames_complete_now(dir / "run.h5.parts" / "rank1.h5") >= 3) {
            const pid_t rank1 = find_rank(tag, 1);
            ASSERT_GT(rank1, 0);
            killed = kill(rank1, SIGKILL) == 0;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_TRUE(killed) << "the run ended before rank 1 could be killed";
    int status = 0;
    waitpid(mpirun, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << status;
    const std::string err = testing::read_text(dir / "mpi.stderr");
    testing::expect_no_sanitizer_report(err, WIFEXITED(status) ? WEXITSTATUS(status) : -1, "mpirun");
    EXPECT_NE(err.find("rank 1"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
    // Whatever each rank flushed is there: rank 1's first 3 frames (30..32) at least.
    std::vector<std::string> parts;
    for (const char* part : {"run.h5.parts/rank0.h5", "run.h5.parts/rank1.h5"}) {
        if (frames_complete_now(dir / part) > 0) parts.push_back(part);
    }
    ASSERT_FALSE(parts.empty());
    EXPECT_GE(frames_complete_now(dir / "run.h5.parts" / "rank1.h5"), 3u);
    const CliResult joined = testing::run_cli(with({"join", "--allow-incomplete", "-o", "kept.h5"}, parts), dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.err;
    EXPECT_EQ(testing::run_cli({"validate", "--allow-incomplete", "kept.h5"}, dir.path()).exit_code, 0);
}

}  // namespace
}  // namespace collidescope
