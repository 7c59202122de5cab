// Frame-parallel runs under MPI (ranks.hpp, docs/how-to/mpi.md): Open MPI's C API, called from the
// main thread only (the engine's worker threads never touch MPI).

#include "ranks/ranks.hpp"

#include "interrupt.hpp"
#include "output_stream.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/join.hpp"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <vector>

namespace collidescope::app::ranks {
namespace {

struct TextOutput {
    std::string target;  ///< what the run delivers: a file or "-"
    std::string local;   ///< this rank's file
};

struct State {
    bool active = false;  ///< MPI started and more than one rank
    int rank = 0;
    int size = 1;
    long job = 0;         ///< rank 0's pid: names the temporary files of this run
    FrameRange block{};
    bool have_block = false;
    std::int64_t frame = -1;  ///< the frame being read or processed, -1 before the first
    std::vector<TextOutput> texts;
    std::vector<std::pair<std::string, RecordingJoin>> recordings;  ///< targets; parts are recording_part(target, join, r)
    /// Under MPI, SIGINT and SIGTERM are caught for the whole run: mpirun passes Ctrl-C on to
    /// every rank as SIGTERM, and a rank that finished its block and waits for the others (or
    /// assembles the outputs) must not die of it, or mpirun kills the ranks still stopping.
    std::optional<InterruptGuard> interrupt;
    std::vector<double> summary_values;   ///< summed over the ranks for summary_line
    std::function<std::string(const std::vector<double>&)> summary_line;
    bool summary_on_stdout = false;
    std::function<int()> last_step;  ///< rank 0's when_done
};

State g_state;

bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(name) != nullptr) return true;
    }
    return false;
}

// A virtual join's parts are its data, kept in a folder of their own beside it; a copying
// join's are removed once joined.
std::string parts_folder(const std::string& target) { return target + ".parts"; }
std::string recording_part(const std::string& target, RecordingJoin join, int rank) {
    if (join == RecordingJoin::Virtual) return parts_folder(target) + "/rank" + std::to_string(rank) + ".h5";
    return target + ".rank" + std::to_string(rank) + ".h5";
}
std::string parts_pattern(const std::string& target, RecordingJoin join) {
    return join == RecordingJoin::Virtual ? parts_folder(target) + "/rank*.h5" : target + ".rank*.h5";
}

constexpr int k_chunk_bytes = 16 << 20;

// Sends this rank's file (or what an interrupted run left: its .partial) to rank 0, then an
// empty message as the end.
void send_file(const std::string& local, int tag) {
    std::string path = local;
    if (!std::filesystem::exists(path)) path = OutputStream::partial_name(local);
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buffer(k_chunk_bytes);
    while (in) {
        in.read(buffer.data(), k_chunk_bytes);
        const auto got = static_cast<int>(in.gcount());
        if (got > 0) MPI_Send(buffer.data(), got, MPI_BYTE, 0, tag, MPI_COMM_WORLD);
    }
    MPI_Send(buffer.data(), 0, MPI_BYTE, 0, tag, MPI_COMM_WORLD);
    in.close();
    std::error_code error;
    std::filesystem::remove(local, error);
    std::filesystem::remove(OutputStream::partial_name(local), error);
}

void receive_into(std::ostream& out, int source, int tag) {
    std::vector<char> buffer;
    for (;;) {
        MPI_Status status;
        MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        buffer.resize(static_cast<std::size_t>(std::max(count, 1)));
        MPI_Recv(buffer.data(), count, MPI_BYTE, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (count == 0) return;
        out.write(buffer.data(), count);
    }
}

// Appends a file to `out` (an empty file adds nothing: no failbit, unlike `out << rdbuf`).
void append_file(const std::string& path, std::ostream& out) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buffer(k_chunk_bytes);
    while (in) {
        in.read(buffer.data(), k_chunk_bytes);
        if (in.gcount() > 0) out.write(buffer.data(), in.gcount());
    }
}

// Rank 0: the output in rank order, complete (renamed to its name) only when every rank was.
// Every rank's data is received whatever fails, so that no rank waits forever on its send.
void assemble_text(const TextOutput& text, int tag, bool complete) {
    std::optional<OutputStream> out;
    std::string failure;
    try {
        out.emplace(text.target);
    } catch (const std::exception& error) {
        failure = error.what();
    }
    std::ostream discard(nullptr);
    std::ostream& sink = out ? out->stream() : discard;
    std::string local = text.local;
    if (!std::filesystem::exists(local)) local = OutputStream::partial_name(text.local);
    append_file(local, sink);
    std::error_code error;
    std::filesystem::remove(text.local, error);
    std::filesystem::remove(OutputStream::partial_name(text.local), error);
    for (int source = 1; source < g_state.size; ++source) receive_into(sink, source, tag);
    if (!failure.empty()) throw InputError(failure);
    if (complete) out->finish();
    else out->finish_partial();
}

int combine(const std::vector<int>& codes) {
    int combined = 0;
    for (const int code : codes) {
        if (code != 0 && code != 1 && code != 130 && code != 143) return 2;
    }
    for (const int code : codes) {
        if (code == 130 || code == 143) return code;
        combined = std::max(combined, code);
    }
    return combined;
}

void print_line(const std::string& line) { std::cerr << "collidescope: " << line << std::endl; }

// Rank 0 prints the summary line of the sums, when every rank registered as many values.
void print_summary() {
    const int count = static_cast<int>(g_state.summary_values.size());
    int fewest = 0, most = 0;
    MPI_Allreduce(&count, &fewest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&count, &most, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (fewest != most || count == 0) return;
    std::vector<double> sums(g_state.summary_values.size());
    MPI_Reduce(g_state.summary_values.data(), sums.data(), count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    if (g_state.rank != 0 || !g_state.summary_line) return;
    std::ostream& out = g_state.summary_on_stdout ? std::cout : std::cerr;
    out << g_state.summary_line(sums) + '\n' << std::flush;
}

// Rank 0: the command's last step (when_done), its code if larger than `code`.
int run_last_step(int code) {
    try {
        return std::max(code, g_state.last_step());
    } catch (const std::exception& error) {
        print_line("error: " + std::string(error.what()));
        return 2;
    }
}

// Rank 0, when ranks were stopped by SIGINT or SIGTERM (mpirun passes Ctrl-C on as SIGTERM):
// one line saying which, after their own lines.
void print_interrupted(const std::vector<int>& codes) {
    std::string stopped;
    int signal = 0;
    for (int r = 0; r < g_state.size; ++r) {
        const int code = codes[static_cast<std::size_t>(r)];
        if (code != 130 && code != 143) continue;
        stopped += (stopped.empty() ? "" : ", ") + std::to_string(r);
        signal = code - 128;
    }
    if (stopped.empty()) return;
    print_line("interrupted: rank(s) " + stopped + " of " + std::to_string(g_state.size) + " stopped by " +
               signal_name(signal) + " after their current frame (mpirun passes Ctrl-C on to the ranks as SIGTERM); "
               "every finished frame is kept");
}

// Rank 0: joins the parts into the target (a copying join then removes them), or says where
// they are.
int assemble_recording(const std::string& target, RecordingJoin join, const std::vector<int>& codes, int code) {
    std::vector<std::filesystem::path> parts;
    std::string failed;
    for (int r = 0; r < g_state.size; ++r) {
        parts.emplace_back(recording_part(target, join, r));
        if (codes[static_cast<std::size_t>(r)] != 0) failed += (failed.empty() ? "" : ", ") + std::to_string(r);
    }
    const std::string pattern = parts_pattern(target, join);
    if (!failed.empty()) {
        print_line("rank(s) " + failed + " did not finish; every rank's finished frames are in " + pattern +
                   " (collidescope join --allow-incomplete " + pattern + " -o " + target + ")");
        return code;
    }
    recorder::JoinOptions options;
    if (join == RecordingJoin::Virtual) options.layout = recorder::JoinLayout::Virtual;
    try {
        const recorder::JoinSummary summary = recorder::join_recordings(parts, target, options);
        std::string line = "joined the " + std::to_string(summary.parts) + " ranks' parts, " + std::to_string(summary.frames) +
                           " frames -> " + target;
        if (join == RecordingJoin::Virtual) {
            line += " (virtual: its data stays in " + parts_folder(target) + "/, which must be kept and moved with it)";
        }
        print_line(line);
    } catch (const std::exception& error) {
        print_line("error: " + std::string(error.what()) + "; the parts are kept: " + pattern);
        return 2;
    }
    if (join == RecordingJoin::Virtual) return code;
    std::error_code error;
    for (const std::filesystem::path& part : parts) std::filesystem::remove(part, error);
    return code;
}

}  // namespace

Launch::Launch(int& argc, char**& argv) {
    if (!launched_by_mpi()) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &g_state.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_state.size);
    long pid = static_cast<long>(getpid());
    MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    g_state.job = pid;
    g_state.active = g_state.size > 1;
    if (g_state.active) g_state.interrupt.emplace();
}

Launch::~Launch() {
    g_state.interrupt.reset();
    int initialized = 0, finalized = 0;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    if (initialized != 0 && finalized == 0) MPI_Finalize();
}

int Launch::finish(int code) {
    if (!g_state.active) return code;
    std::vector<int> codes(static_cast<std::size_t>(g_state.size));
    MPI_Allgather(&code, 1, MPI_INT, codes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int combined = combine(codes);
    // Every rank registers the same outputs, unless one failed before it got there.
    const int texts = static_cast<int>(g_state.texts.size());
    int fewest = 0, most = 0;
    MPI_Allreduce(&texts, &fewest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&texts, &most, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    const bool complete = std::all_of(codes.begin(), codes.end(), [](int c) { return c == 0 || c == 1; });
    if (fewest == most) {
        for (int i = 0; i < texts; ++i) {
            const TextOutput& text = g_state.texts[static_cast<std::size_t>(i)];
            if (g_state.rank == 0) {
                try {
                    assemble_text(text, i, complete);
                } catch (const std::exception& error) {
                    print_line("error: " + std::string(error.what()));
                    combined = 2;
                }
            } else {
                send_file(text.local, i);
            }
        }
    }
    print_summary();
    if (g_state.rank == 0) print_interrupted(codes);
    if (g_state.rank == 0 && complete && combined < 2 && g_state.last_step) combined = run_last_step(combined);

    if (g_state.rank == 0) {
        for (const auto& [target, join] : g_state.recordings) combined = assemble_recording(target, join, codes, combined);
    }
    MPI_Bcast(&combined, 1, MPI_INT, 0, MPI_COMM_WORLD);
    // The run's code comes from rank 0 alone: mpirun exits with the first non-zero code a rank
    // returns, and then names that rank in its report.
    return g_state.rank == 0 ? combined : 0;
}

bool parallel() { return g_state.active; }

bool leader() { return g_state.rank == 0; }

void when_done(std::function<int()> step) {
    if (g_state.active && g_state.rank == 0) g_state.last_step = std::move(step);
}

void summary_line(std::vector<double> values, std::function<std::string(const std::vector<double>&)> line, bool on_stdout) {
    if (!g_state.active) return;
    g_state.summary_on_stdout = on_stdout;
    g_state.summary_values = std::move(values);
    g_state.summary_line = std::move(line);
}

FrameRange block(FrameRange range) {
    if (!g_state.active) return range;
    g_state.block = block_of(range, g_state.rank, g_state.size);
    g_state.have_block = true;
    return g_state.block;
}

std::string text_output(const std::string& target) {
    if (!g_state.active) return target;
    const std::string local = (std::filesystem::temp_directory_path() /
                               ("collidescope-" + std::to_string(g_state.job) + "-rank" + std::to_string(g_state.rank) +
                                "-" + std::to_string(g_state.texts.size())))
                                  .string();
    g_state.texts.push_back({target, local});
    return local;
}

std::string recording_output(const std::string& target, RecordingJoin join) {
    if (!g_state.active) return target;
    g_state.recordings.emplace_back(target, join);
    if (join == RecordingJoin::Virtual) {
        std::error_code error;  // every rank tries; the recorder names the file if it cannot write there
        std::filesystem::create_directories(parts_folder(target), error);
    }
    return recording_part(target, join, g_state.rank);
}

std::uint32_t at_frame(std::uint32_t frame) {
    g_state.frame = frame;
    return frame;
}

std::string error_prefix() {
    if (!g_state.active) return "";
    std::string prefix = "rank " + std::to_string(g_state.rank) + " of " + std::to_string(g_state.size);
    if (g_state.have_block) {
        prefix += ", frames " + std::to_string(g_state.block.begin) + ".." + std::to_string(g_state.block.end - 1);
    }
    if (g_state.frame >= 0) prefix += ", at frame " + std::to_string(g_state.frame);
    return prefix + ": ";
}

}  // namespace collidescope::app::ranks
