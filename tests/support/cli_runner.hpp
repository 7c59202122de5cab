#pragma once
// Helpers of the end-to-end tests: run the built `collidescope` (COLLIDESCOPE_BIN) with
// arguments in a directory, capture stdout, stderr and the exit code; parse the pairs TSV;
// write scenes as frame-pattern PLY files.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace collidescope::testing {

/// What one run of the command line produced.
struct CliResult {
    int exit_code = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
    /// stderr split into lines (without newlines).
    std::vector<std::string> err_lines() const;
};

/// Runs COLLIDESCOPE_BIN with `args` (each passed as one shell word) in `directory`. A
/// sanitizer report on its stderr fails the test, whatever the exit code
/// (support/sanitizer_report.hpp); so does CliProcess::wait.
CliResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& directory);

/// run_cli for any program (a path), with the same sanitizer check.
CliResult run_program(const std::string& program, const std::vector<std::string>& args,
                      const std::filesystem::path& directory);

/// COLLIDESCOPE_BIN running in the background, for tests that signal it or limit its writes.
/// stdout and stderr go to cli.stdout and cli.stderr in its directory.
class CliProcess {
public:
    /// Starts it in `directory`. `file_size_limit` > 0 sets RLIMIT_FSIZE in the child with
    /// SIGXFSZ ignored, so a write past that size fails with EFBIG, as on a full disk.
    CliProcess(const std::vector<std::string>& args, const std::filesystem::path& directory,
               std::uint64_t file_size_limit = 0);
    /// Kills (SIGKILL) and reaps it if it still runs.
    ~CliProcess();
    CliProcess(const CliProcess&) = delete;
    CliProcess& operator=(const CliProcess&) = delete;

    /// stderr so far.
    std::string err() const;
    /// Polls until `done()` holds (true) or the process ends or `seconds` pass (false).
    bool wait_until(const std::function<bool()>& done, double seconds = 120);
    void send(int signal);
    /// Waits for the end. exit_code: the status it exited with, -1 when a signal ended it.
    CliResult wait();
    /// The signal that ended it (after wait), or 0.
    int term_signal() const { return m_term_signal; }

private:
    std::filesystem::path m_directory;
    std::string m_command;  ///< its arguments, for messages
    int m_pid = -1;
    int m_term_signal = 0;
};

/// One line of the pairs TSV.
struct FramePair {
    std::uint32_t frame = 0;
    TrianglePair pair;
    friend auto operator<=>(const FramePair&, const FramePair&) = default;
};

/// Parses pairs TSV strictly: every line exactly five tab-separated decimal numbers, each
/// line ending in '\n'. Adds a test failure naming the line otherwise.
std::vector<FramePair> parse_pairs_tsv(const std::string& text);

/// Writes every object of `scene` as `<directory>/<name>.%04d.ply` (float32 binary PLY, frame
/// numbers from `first_number`) and returns the patterns, in object order.
std::vector<std::string> write_scene_files(const Scene& scene, const std::filesystem::path& directory,
                                           int first_number = 0);

/// The reference pairs of every frame of `scene` (support/brute_reference), as TSV lines.
std::vector<FramePair> reference_frame_pairs(const Scene& scene, bool self_collision);

/// The text of a file.
std::string read_text(const std::filesystem::path& file);

/// The number of newlines in `text`.
std::size_t line_count(const std::string& text);

}  // namespace collidescope::testing
