// bench's plots: the project's one plotting stack is matplotlib, so `collidescope bench` hands
// its frames.csv to bench/scripts/plot_bench.py (installed as share/collidescope/plot_bench.py)
// and waits for it.

#include "bench_report.hpp"

#include "collidescope/error.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

extern char** environ;

namespace collidescope::app {
namespace {

// The installed copy beside the program (PREFIX/bin/collidescope -> PREFIX/share/collidescope),
// else the source tree's, which the build knows.
std::filesystem::path plot_script() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path installed = program.parent_path().parent_path() / "share/collidescope/plot_bench.py";
        if (std::filesystem::exists(installed, error)) return installed;
    }
    return COLLIDESCOPE_PLOT_SCRIPT;
}

}  // namespace

void draw_plots(const std::filesystem::path& directory) {
    const std::string python = "/usr/bin/python3";
    const std::string script = plot_script().string();
    const std::string folder = directory.string();
    std::vector<char*> argv = {const_cast<char*>(python.c_str()), const_cast<char*>(script.c_str()),
                               const_cast<char*>(folder.c_str()), nullptr};
    const std::string command = python + " " + script + " " + folder;
    pid_t child = 0;
    if (const int error = ::posix_spawn(&child, python.c_str(), nullptr, nullptr, argv.data(), environ); error != 0) {
        throw InputError(command + ": cannot start (" + std::strerror(error) +
                         "); the plots need Debian's python3 and python3-matplotlib (scripts/setup.sh installs them)");
    }
    int status = 0;
    while (::waitpid(child, &status, 0) < 0) {
        if (errno != EINTR) throw InputError(command + ": lost the plotting process: " + std::strerror(errno));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw InputError(command + ": drawing the plots failed (" +
                         (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status)) : std::string("killed")) +
                         "; it needs python3-matplotlib); the CSV files are written");
    }
}

}  // namespace collidescope::app
