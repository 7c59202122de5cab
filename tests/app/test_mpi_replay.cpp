// Under mpirun (app/ranks/ranks.hpp, docs/how-to/mpi.md), beyond the blocks of test_mpi_ranks.cpp: `replay`
// on 2 and 3 ranks writes the serial replay's PNGs, contact sheet and clip byte for byte;
// `check` prints one total line for the run, in the serial line's form; Ctrl-C (SIGINT
// to mpirun) stops every rank of a `record` after its current frame, with the documented line
// and exit code, and leaves parts that `validate` and `join --allow-incomplete` read; and of a
// `check`, leaving one partial pairs file with every rank's finished frames and one total line.

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

#include <algorithm>
#include <chrono>
#include <functional>
#include <regex>
#include <thread>


namespace collidescope {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing_files::TempDir;
using testing_mpi::frames_complete_now;
using testing_mpi::run_mpi;
using testing_mpi::with;

// Every file under `dir`, relative names, sorted.
std::vector<std::string> files_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(MpiReplay, TwoAndThreeRanksWriteTheSerialPngsAndContactSheetByteForByte) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    ASSERT_EQ(testing::run_cli({"record", "--scene", "D:small", "--method", "aabb", "--threads", "1", "-q", "-o", "run.h5"},
                               dir.path())
                  .exit_code,
              0);
    // The options that depend on every frame: the focus path, the orbit's angle, the sheet's choice.
    for (const std::string camera : {"focus", "orbit"}) {
        SCOPED_TRACE("--camera " + camera);
        const std::vector<std::string> replay = {"replay", "run.h5", "--size", "256x192", "--threads", "1", "--camera",
                                                 camera, "--sheet-frames", "collisions", "--sheet-count", "5"};
        const CliResult serial = testing::run_cli(with(replay, {"-o", "serial", "--contact-sheet", "serial.png"}), dir.path());
        ASSERT_EQ(serial.exit_code, 0) << serial.err;
        const std::vector<std::string> names = files_in(dir / "serial");
        ASSERT_EQ(names.size(), 16u);
        // Two ranks and three (an uneven split); a sanitizer build two only.
        for (const int ranks : testing::sweep_of(std::vector<int>{2, 3}, 2)) {
            SCOPED_TRACE(std::to_string(ranks) + " ranks");
            fs::remove_all(dir / "mpi");
            const CliResult parallel = run_mpi(ranks, with(replay, {"-o", "mpi", "--contact-sheet", "mpi.png"}), dir.path());
            ASSERT_EQ(parallel.exit_code, 0) << parallel.err;
            EXPECT_EQ(files_in(dir / "mpi"), names);
            for (const std::string& name : names) {
                EXPECT_TRUE(testing::read_text(dir / "mpi" / name) == testing::read_text(dir / "serial" / name)) << name;
            }
            EXPECT_TRUE(testing::read_text(dir / "mpi.png") == testing::read_text(dir / "serial.png"));
            // One line for the run, as serially (rank 0 prints it when every rank is done).
            EXPECT_NE(parallel.out.find("wrote 16 frames to mpi (frame_0000.png .. frame_0015.png)\n"), std::string::npos)
                << parallel.out;
            EXPECT_EQ(parallel.out.find("wrote", parallel.out.find("wrote") + 1), std::string::npos) << parallel.out;
        }
    }
}

// Rank 0 encodes the clip from every rank's PNGs once they are written: the serial clip, byte
// for byte (the encoder sees the same pixels, in the same order).
TEST(MpiReplay, VideoIsEncodedByRankZeroAsTheSerialClip) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    ASSERT_EQ(testing::run_cli({"record", "--scene", "D:small", "--frames", ":9", "-q", "-o", "run.h5"}, dir.path()).exit_code, 0);
    const std::vector<std::string> replay = {"replay", "run.h5", "--size", "128x96", "--threads", "1", "-q"};
    for (const std::string clip : {"clip.mp4", "clip.gif"}) {
        SCOPED_TRACE(clip);
        const CliResult serial = testing::run_cli(with(replay, {"-o", "serial", "--video", "serial-" + clip}), dir.path());
        ASSERT_EQ(serial.exit_code, 0) << serial.err;
        const CliResult parallel = run_mpi(2, with(replay, {"-o", "mpi", "--video", "mpi-" + clip}), dir.path());
        ASSERT_EQ(parallel.exit_code, 0) << parallel.err;
        EXPECT_NE(parallel.out.find("video: mpi-" + clip + " (9 frames at "), std::string::npos) << parallel.out;
        ASSERT_TRUE(fs::exists(dir / ("mpi-" + clip)));
        EXPECT_TRUE(testing::read_text(dir / ("mpi-" + clip)) == testing::read_text(dir / ("serial-" + clip)));
    }
    // The ranks need somewhere to put the frames.
    const CliResult alone = run_mpi(2, with(replay, {"--video", "alone.mp4"}), dir.path());
    EXPECT_EQ(alone.exit_code, 2);
    EXPECT_NE(alone.err.find("rank 0 of 2: under mpirun, --video needs -o DIR"), std::string::npos) << alone.err;
    EXPECT_FALSE(fs::exists(dir / "alone.mp4"));
}

// "total: F frames, C with collisions, P colliding pairs, T ms" -> "F C P".
std::string counts_of_total(const std::string& err) {
    std::smatch match;
    const std::regex line("(^|\n)total: ([0-9]+) frames, ([0-9]+) with collisions, ([0-9]+) colliding pairs, [0-9.]+ ms");
    if (!std::regex_search(err, match, line)) return "no total line";
    return match[2].str() + " " + match[3].str() + " " + match[4].str();
}

TEST(MpiCheck, RankZeroPrintsOneTotalLineInTheSerialForm) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    const std::vector<std::string> check = {"check", "--scene", "C:small", "--frames", ":12", "--method", "aabb",
                                            "--threads", "1", "-q"};
    const CliResult serial = testing::run_cli(check, dir.path());
    ASSERT_EQ(serial.exit_code, 1) << serial.err;
    ASSERT_NE(counts_of_total(serial.err), "no total line") << serial.err;
    for (const int ranks : {2, 3}) {
        const CliResult parallel = run_mpi(ranks, check, dir.path());
        EXPECT_EQ(parallel.exit_code, 1) << parallel.err;
        EXPECT_EQ(counts_of_total(parallel.err), counts_of_total(serial.err)) << parallel.err;
        const std::regex line("(^|\n)total: [^\n]* ms; " + std::to_string(ranks) + " ranks, [0-9.]+ s wall time\n");
        EXPECT_TRUE(std::regex_search(parallel.err, line)) << parallel.err;
        std::size_t lines = 0;
        for (std::size_t at = parallel.err.find("total:"); at != std::string::npos; at = parallel.err.find("total:", at + 1)) ++lines;
        EXPECT_EQ(lines, 1u) << parallel.err;
    }
}


// Runs `command` (mpirun_command without a time limit: the shell execs mpirun), sends mpirun
// SIGINT once `ready()` holds, as Ctrl-C at a terminal does (the ranks are in process groups of
// their own; Open MPI 4.1 passes it on to them as SIGTERM, docs/how-to/mpi.md), and returns mpirun's
// wait status. Fails the test when the run ended before `ready()` or still ran after 240 s.
// mpirun's wait before it passes a SIGINT on as SIGTERM, and again before SIGKILL: longer than
// Open MPI's one second, so a loaded CI machine finishes the frame and closes the outputs in it.
constexpr int kGraceSeconds = 3;

int sigint_to_mpirun_when(const std::string& command, const std::function<bool()>& ready) {
    const pid_t mpirun = testing_mpi::spawn_shell(command);
    EXPECT_GT(mpirun, 0);
    if (mpirun <= 0) return -1;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(240);
    bool sent = false;
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        if (waitpid(mpirun, &status, WNOHANG) == mpirun) {
            EXPECT_TRUE(sent) << "the run ended before it was ready for SIGINT";
            return status;
        }
        if (!sent && ready()) sent = kill(mpirun, SIGINT) == 0;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(mpirun, SIGKILL);
    waitpid(mpirun, &status, 0);
    ADD_FAILURE() << "mpirun still ran 240 s after the start" << (sent ? " (it hung after SIGINT)" : "");
    return -1;
}

TEST(MpiInterrupt, SigintToMpirunStopsEveryRankAfterItsFrameAndKeepsTheParts) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    // C's 200 frames at its large preset, 100 a rank, some 100 ms a frame here (at the default
    // preset, about 10 ms a frame since the traversal between objects went wide, rank 1 once
    // finished its block before mpirun passed the SIGINT on, on CI). A small writer queue keeps
    // the writer close behind. mpirun's grace is three seconds, not its default one: on CI, with
    // another test on both cores, the ranks (whose writers run at nice 10) were once killed
    // before they closed their parts, and printed nothing. The SIGTERM then comes about 3.5 s
    // after the start, near frame 35 of a block of about 11 s here.
    const std::string command = testing_mpi::mpirun_command(
        2, {"record", "--scene", "C:large", "--method", "aabb", "--threads", "1", "--queue-memory", "2M", "-q", "-o", "run.h5"},
        dir.path(), 0, kGraceSeconds);
    const int status = sigint_to_mpirun_when(command, [&] {
        return frames_complete_now(dir / "run.h5.parts" / "rank0.h5") >= 3 && frames_complete_now(dir / "run.h5.parts" / "rank1.h5") >= 3;
    });
    ASSERT_FALSE(HasFailure());
    // mpirun's own code for a job it aborted: 1 (not the ranks' 143).
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
    const std::string err = testing::read_text(dir / "mpi.stderr");
    testing::expect_no_sanitizer_report(err, WIFEXITED(status) ? WEXITSTATUS(status) : -1, "mpirun");
    EXPECT_NE(err.find("collidescope: interrupted: rank(s) 0, 1 of 2 stopped by SIGTERM after their current frame"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("collidescope join --allow-incomplete run.h5.parts/rank*.h5 -o run.h5"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
    std::vector<std::string> parts;
    for (const char* part : {"run.h5.parts/rank0.h5", "run.h5.parts/rank1.h5"}) {
        SCOPED_TRACE(part);
        const std::uint64_t frames = frames_complete_now(dir / part);
        EXPECT_GE(frames, 3u);
        EXPECT_LT(frames, 100u) << "the rank was not stopped";
        EXPECT_EQ(testing::run_cli({"validate", "--allow-incomplete", part}, dir.path()).exit_code, 0);
        EXPECT_EQ(recorder::Recording(dir / part).interrupted(), "SIGTERM");
        parts.push_back(part);
    }
    const CliResult joined = testing::run_cli(with({"join", "--allow-incomplete", "-o", "kept.h5"}, parts), dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.err;
    EXPECT_EQ(testing::run_cli({"validate", "--allow-incomplete", "kept.h5"}, dir.path()).exit_code, 0);
}

TEST(MpiInterrupt, SigintToMpirunStopsACheckWithOnePartialOutputAndOneTotalLine) {
    COLLIDESCOPE_REQUIRE_MPI();
    TempDir dir;
    // C at its large preset: some 75 ms a frame here. At the default preset (about 10 ms a
    // frame once the traversal between objects went wide) both ranks could finish their
    // blocks between the SIGINT and mpirun passing it on, and the test failed on a fresh VM.
    const std::vector<std::string> check = {"check", "--scene", "C:large", "--method", "aabb", "--threads", "1",
                                            "--exit-zero"};
    // Each rank logs a line per frame: SIGINT once rank 0 finished frame 8 and rank 1 frame 103
    // (both have pairs by then: C has none before frame 5, at either preset).
    const int status = sigint_to_mpirun_when(testing_mpi::mpirun_command(2, with(check, {"--pairs", "pairs.tsv"}), dir.path(), 0, kGraceSeconds),
                                             [&] {
                                                 const std::string err = testing::read_text(dir / "mpi.stderr");
                                                 return err.find("frame 8:") != std::string::npos &&
                                                        err.find("frame 103:") != std::string::npos;
                                             });
    ASSERT_FALSE(HasFailure());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
    const std::string err = testing::read_text(dir / "mpi.stderr");
    testing::expect_no_sanitizer_report(err, WIFEXITED(status) ? WEXITSTATUS(status) : -1, "mpirun");
    EXPECT_NE(err.find("collidescope: interrupted: rank(s) 0, 1 of 2 stopped by SIGTERM"), std::string::npos) << err;
    EXPECT_NE(err.find("partial output: pairs.tsv.partial\n"), std::string::npos) << err;
    EXPECT_NE(err.find("\ntotal: "), std::string::npos) << err;
    EXPECT_EQ(err.find("total:"), err.rfind("total:")) << "one total line: " << err;
    // The partial output: a prefix of each block's pairs, in frame order (every finished frame).
    EXPECT_FALSE(fs::exists(dir / "pairs.tsv"));
    const std::vector<testing::FramePair> kept = testing::parse_pairs_tsv(testing::read_text(dir / "pairs.tsv.partial"));
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    const bool from_both = !kept.empty() && kept.front().frame < 100 && kept.back().frame >= 100;
    ASSERT_TRUE(from_both) << kept.size() << " pairs kept";
    // Each block's last kept frame, and the serial run's pairs of the frames up to it: what was
    // kept (a serial run of the kept frames only, not of all 200: under the sanitizers the
    // whole serial run took over two minutes).
    std::uint32_t last[2] = {0, 0};
    for (const testing::FramePair& p : kept) last[p.frame >= 100] = std::max(last[p.frame >= 100], p.frame);
    EXPECT_LT(last[0], 99u) << "rank 0 was not stopped";
    EXPECT_LT(last[1], 199u) << "rank 1 was not stopped";
    std::vector<testing::FramePair> serial;
    for (const auto& [from, to] : {std::pair{0u, last[0] + 1}, std::pair{100u, last[1] + 1}}) {
        const std::string frames = std::to_string(from) + ":" + std::to_string(to);
        ASSERT_EQ(testing::run_cli(with(check, {"-q", "--frames", frames, "--pairs", "serial.tsv"}), dir.path()).exit_code, 0);
        const std::vector<testing::FramePair> part = testing::parse_pairs_tsv(testing::read_text(dir / "serial.tsv"));
        serial.insert(serial.end(), part.begin(), part.end());
    }
    EXPECT_EQ(kept, serial);
}

}  // namespace
}  // namespace collidescope
