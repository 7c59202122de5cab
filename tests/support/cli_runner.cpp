// Running the command line from tests.

#include "support/cli_runner.hpp"

#include "support/brute_reference.hpp"
#include "support/sanitizer_report.hpp"

#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace collidescope::testing {
namespace {

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word) {
        if (c == '\'') {
            quoted += "'\\''";  // close, escaped quote, reopen
        } else {
            quoted += c;
        }
    }
    quoted += '\'';
    return quoted;
}

std::string frame_file_name(const std::string& name, int number) {
    char digits[16];
    std::snprintf(digits, sizeof digits, "%04d", number);
    return name + "." + digits + ".ply";
}

}  // namespace

std::vector<std::string> CliResult::err_lines() const {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::size_t line_count(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

CliProcess::CliProcess(const std::vector<std::string>& args, const std::filesystem::path& directory,
                       std::uint64_t file_size_limit)
    : m_directory(directory) {
    // Everything the child needs is prepared before fork: after it, only async-signal-safe calls.
    const std::string dir = directory.string();
    const std::string out = (directory / "cli.stdout").string();
    const std::string err = (directory / "cli.stderr").string();
    std::vector<std::string> words = {COLLIDESCOPE_BIN};
    words.insert(words.end(), args.begin(), args.end());
    for (const std::string& arg : args) m_command += (m_command.empty() ? "" : " ") + arg;
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null_fd = open("/dev/null", O_RDONLY);
        if (chdir(dir.c_str()) != 0 || out_fd < 0 || err_fd < 0 || null_fd < 0) _exit(127);
        dup2(null_fd, STDIN_FILENO);
        dup2(out_fd, STDOUT_FILENO);
        dup2(err_fd, STDERR_FILENO);
        if (file_size_limit > 0) {
            const rlimit limit = {file_size_limit, file_size_limit};
            setrlimit(RLIMIT_FSIZE, &limit);
            signal(SIGXFSZ, SIG_IGN);  // kept across exec: writes fail with EFBIG instead
        }
        execv(argv[0], argv.data());
        _exit(127);
    }
    EXPECT_GT(pid, 0) << "fork failed";
    m_pid = pid;
}

CliProcess::~CliProcess() {
    if (m_pid <= 0) return;
    kill(m_pid, SIGKILL);
    waitpid(m_pid, nullptr, 0);
}

std::string CliProcess::err() const { return read_text(m_directory / "cli.stderr"); }

bool CliProcess::wait_until(const std::function<bool()>& done, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (done()) return true;
        // Ended (a zombie until wait()): one last look.
        siginfo_t info{};
        if (waitid(P_PID, static_cast<id_t>(m_pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid != 0) {
            return done();
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

void CliProcess::send(int signal) { kill(m_pid, signal); }

CliResult CliProcess::wait() {
    int status = 0;
    waitpid(m_pid, &status, 0);
    m_pid = -1;
    CliResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    m_term_signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    result.out = read_text(m_directory / "cli.stdout");
    result.err = read_text(m_directory / "cli.stderr");
    expect_no_sanitizer_report(result.err, result.exit_code, "collidescope " + m_command);
    return result;
}

CliResult run_program(const std::string& program, const std::vector<std::string>& args,
                      const std::filesystem::path& directory) {
    const std::filesystem::path out = directory / "cli.stdout";
    const std::filesystem::path err = directory / "cli.stderr";
    std::string command = "cd ";
    command += shell_quote(directory.string());
    command += " && ";
    command += shell_quote(program);
    std::string described = std::filesystem::path(program).filename().string();
    for (const std::string& arg : args) {
        command += ' ';
        command += shell_quote(arg);
        described += ' ';
        described += arg;
    }
    command += " </dev/null >";
    command += shell_quote(out.string());
    command += " 2>";
    command += shell_quote(err.string());
    const int status = std::system(command.c_str());
    CliResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(out);
    result.err = read_text(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    expect_no_sanitizer_report(result.err, result.exit_code, described);
    return result;
}

CliResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& directory) {
    return run_program(COLLIDESCOPE_BIN, args, directory);
}

std::vector<FramePair> parse_pairs_tsv(const std::string& text) {
    std::vector<FramePair> pairs;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (end == std::string::npos) ADD_FAILURE() << "last line without newline: " << line;
        std::uint32_t fields[5] = {};
        const char* cursor = line.data();
        const char* const line_end = line.data() + line.size();
        bool ok = true;
        for (int k = 0; k < 5 && ok; ++k) {
            const auto [next, error] = std::from_chars(cursor, line_end, fields[k]);
            ok = error == std::errc() && next != cursor && (k == 4 ? next == line_end : next != line_end && *next == '\t');
            cursor = next + 1;
        }
        if (!ok) {
            ADD_FAILURE() << "malformed TSV line: '" << line << "'";
            break;
        }
        pairs.push_back({fields[0], {fields[1], fields[2], fields[3], fields[4]}});
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return pairs;
}

std::vector<std::string> write_scene_files(const Scene& scene, const std::filesystem::path& directory,
                                           int first_number) {
    std::vector<std::string> patterns;
    for (std::uint32_t o = 0; o < scene.source->object_count(); ++o) {
        patterns.push_back((directory / (scene.source->object_name(o) + ".%04d.ply")).string());
    }
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        for (std::uint32_t o = 0; o < frame.objects.size(); ++o) {
            const MeshData mesh{frame.objects[o].vertices.to_vector(), frame.objects[o].topology->triangles};
            write_ply(directory / frame_file_name(scene.source->object_name(o), first_number + static_cast<int>(f)), mesh);
        }
    }
    return patterns;
}

std::vector<FramePair> reference_frame_pairs(const Scene& scene, bool self_collision) {
    std::vector<FramePair> pairs;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        for (const TrianglePair& pair : reference_colliding_pairs(scene.source->frame(f), self_collision)) {
            pairs.push_back({f, pair});
        }
    }
    return pairs;
}

}  // namespace collidescope::testing
