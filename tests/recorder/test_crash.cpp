// Crash safety: `record` killed with SIGKILL at seeded random frames leaves a file that opens
// (through the tool's reader and h5py), reports its complete frames, and holds every one of
// them intact: equal to the same frames of an uninterrupted recording.

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

extern char** environ;

namespace collidescope {
namespace {

using testing_files::TempDir;

pid_t spawn_record(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(COLLIDESCOPE_BIN));
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, COLLIDESCOPE_BIN, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    EXPECT_EQ(error, 0);
    return pid;
}

// Kills the recording once at least `target` frames are complete; returns false when the
// process ended on its own first.
bool kill_after(pid_t pid, const std::filesystem::path& file, std::uint64_t target) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid) return false;
        if (testing::frames_complete_now(file) >= target) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    return false;
}

// The complete rows equal the whole recording's, counts included.
void expect_rows_equal(const recorder::Recording& killed, const recorder::Recording& whole) {
    testing::expect_complete_rows_equal(killed, whole);
    const auto counts = killed.counts();
    const auto whole_counts = whole.counts();
    for (std::uint64_t r = 0; r < killed.frames_complete(); ++r) {
        for (std::size_t c = 0; c < counts.size(); ++c) EXPECT_EQ(counts[c].values[r], whole_counts[c].values[r]);
    }
}

TEST(RecorderCrash, SigkillKeepsEveryFinishedFrame) {
    TempDir dir;
    // Kills come after 1 to 50 frames; the other 350 (about 1.4 s of recording) leave the
    // poller below room to see its target before the recording ends on its own. With 80
    // frames (~0.1 s of margin) the test failed once in 24 runs on a heavily loaded machine.
    constexpr std::uint32_t k_frames = 400;
    const std::vector<std::string> inputs = testing::write_scene_files(testing::crossing_sheets(40, k_frames), dir.path());
    std::vector<std::string> args = inputs;
    args.insert(args.end(), {"--threads", "1", "-q", "-o"});

    std::vector<std::string> whole_args = args;
    whole_args.push_back((dir.path() / "whole.h5").string());
    const testing::CliResult whole_run = testing::run_cli([&] {
        std::vector<std::string> a = {"record"};
        a.insert(a.end(), whole_args.begin(), whole_args.end());
        return a;
    }(), dir.path());
    ASSERT_EQ(whole_run.exit_code, 0) << whole_run.err;
    const recorder::Recording whole(dir.path() / "whole.h5");
    ASSERT_EQ(whole.frames_complete(), k_frames);

    const unsigned seed = 20261122;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::uint64_t> pick(1, 50);
    for (int attempt = 0; attempt < 3; ++attempt) {
        const std::uint64_t target = pick(rng);
        SCOPED_TRACE("seed " + std::to_string(seed) + ", kill after frame " + std::to_string(target));
        std::printf("kill test: seed %u, kill once %llu frames are complete\n", seed, static_cast<unsigned long long>(target));
        const std::filesystem::path file = dir.path() / ("killed" + std::to_string(attempt) + ".h5");
        std::vector<std::string> run_args = {"record"};
        run_args.insert(run_args.end(), args.begin(), args.end());
        run_args.push_back(file.string());
        ASSERT_TRUE(kill_after(spawn_record(run_args), file, target)) << "the recording ended before the kill";

        const recorder::Recording killed(file);
        EXPECT_FALSE(killed.finished());
        EXPECT_GE(killed.frames_complete(), target);
        EXPECT_LT(killed.frames_complete(), k_frames);
        std::printf("  killed with %llu frames complete\n", static_cast<unsigned long long>(killed.frames_complete()));
        expect_rows_equal(killed, whole);

        EXPECT_EQ(testing::run_cli({"validate", "--allow-incomplete", file.string()}, dir.path()).exit_code, 0);
        EXPECT_EQ(testing::run_cli({"validate", file.string()}, dir.path()).exit_code, 1);
        const std::string command = "/usr/bin/python3 -c \"import h5py, sys; f = h5py.File(sys.argv[1], 'r', swmr=True); "
                                    "sys.exit(0 if len(f['frames/index']) >= int(sys.argv[2]) else 1)\" '" +
                                    file.string() + "' " + std::to_string(killed.frames_complete());
        EXPECT_EQ(std::system(command.c_str()), 0) << "h5py cannot read the killed recording";
    }
}

}  // namespace
}  // namespace collidescope
