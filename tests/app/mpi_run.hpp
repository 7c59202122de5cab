#pragma once
// Running the built collidescope under mpirun from a test (test_mpi_ranks.cpp, test_mpi_replay.cpp): Open MPI
// refuses to run as root (CI does) unless told, and the ranks run without leak detection in
// the AddressSanitizer build (scripts/sanitize.sh address): they still check memory errors, but
// Open MPI's components are dlopen'ed and closed again by MPI_Finalize, so the memory they keep
// is reported with stacks that end in "<unknown module>", which no suppression can name
// (docs/how-to/sanitizers.md); the serial tests check the same code for leaks. Under CI=true a build
// without Open MPI, or no mpirun, fails the tests instead of skipping them.

#include "support/ci.hpp"
#include "support/cli_runner.hpp"
#include "support/sanitizer_report.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace collidescope::testing_mpi {

/// Why MPI runs cannot be tested here, or "".
inline std::string mpi_missing() {
#if !COLLIDESCOPE_MPI
    return "collidescope was built without Open MPI (libopenmpi-dev)";
#endif
    if (std::system("command -v mpirun > /dev/null 2>&1") != 0) return "mpirun is not on PATH (openmpi-bin)";
    return "";
}

#define COLLIDESCOPE_REQUIRE_MPI()                                                                           \
    do {                                                                                                     \
        const std::string missing = ::collidescope::testing_mpi::mpi_missing();                              \
        if (!missing.empty()) {                                                                              \
            COLLIDESCOPE_SKIP_OR_FAIL_UNDER_CI(missing << " (scripts/setup.sh installs Open MPI)");         \
        }                                                                                                    \
    } while (0)

inline std::string quoted(const std::string& word) {
    std::string out = "'";
    for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// The shell command that runs `args` on `ranks` ranks in `dir`, output to mpi.stdout and
/// mpi.stderr there. `exec`s mpirun itself, so a shell started with it becomes mpirun (a test
/// can signal that pid); `limit` > 0 ends a run that hangs after that many seconds (exit 124),
/// through `timeout`, which then sits between the shell and mpirun. `sigkill_timeout` > 0 sets
/// mpirun's `odls_base_sigkill_timeout` (its wait before SIGTERM after a SIGINT, and again before
/// SIGKILL; docs/how-to/mpi.md), 0 keeps Open MPI's default of one second.
inline std::string mpirun_command(int ranks, const std::vector<std::string>& args, const std::filesystem::path& dir,
                                  int limit = 300, int sigkill_timeout = 0) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    std::string command = "cd " + quoted(dir.string()) + " && exec env ASAN_OPTIONS=detect_leaks=0 " +
                          (limit > 0 ? "timeout " + std::to_string(limit) + " " : std::string()) +
                          "mpirun --oversubscribe " +
                          (sigkill_timeout > 0 ? "--mca odls_base_sigkill_timeout " + std::to_string(sigkill_timeout) + " " : std::string()) +
                          "-np " + std::to_string(ranks) + " " + quoted(COLLIDESCOPE_BIN);
    for (const std::string& arg : args) command += ' ' + quoted(arg);
    return command + " > mpi.stdout 2> mpi.stderr";
}

/// Runs `args` on `ranks` ranks in `dir` and waits.
inline testing::CliResult run_mpi(int ranks, const std::vector<std::string>& args, const std::filesystem::path& dir) {
    const int status = std::system(mpirun_command(ranks, args, dir).c_str());
    testing::CliResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = testing::read_text(dir / "mpi.stdout");
    result.err = testing::read_text(dir / "mpi.stderr");
    testing::expect_no_sanitizer_report(result.err, result.exit_code, "mpirun -n " + std::to_string(ranks) + " collidescope");
    return result;
}

inline std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

/// Starts `/bin/sh -c command` without waiting (mpirun_command execs mpirun, so the pid is
/// mpirun's); -1 when it could not be started.
inline pid_t spawn_shell(std::string command) {
    std::string shell = "/bin/sh", flag = "-c";
    char* argv[] = {shell.data(), flag.data(), command.data(), nullptr};
    pid_t pid = -1;
    return posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv, environ) == 0 ? pid : -1;
}

/// Complete frames of a recording being written (SWMR), 0 while it cannot be read yet.
inline std::uint64_t frames_complete_now(const std::filesystem::path& file) {
    try {
        return recorder::Recording(file).frames_complete();
    } catch (const InputError&) {
        return 0;
    }
}

}  // namespace collidescope::testing_mpi
