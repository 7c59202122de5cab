#pragma once
// Frame-parallel runs under MPI: `mpirun -np N collidescope check|record|replay ...` with the same
// arguments as a serial run (docs/how-to/mpi.md). Each rank takes one contiguous block of the frames
// (cold: its trees are built at its first frame, the adaptive policy starts from its priors),
// writes its outputs to files of its own, and rank 0 assembles them, in frame order, into the
// outputs a serial run writes. Without mpirun (or with one rank) every function here is the
// identity and MPI is not started: a serial run is exactly what it was.
//
// The engine knows nothing of this; the commands ask for their block and their output names.

#include "frame_range.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace collidescope::app::ranks {

/// Rank `rank` of `size`'s block of `range`: contiguous, in rank order, sizes differing by at
/// most one frame (the first range.size % size ranks take one more). Throws InputError when
/// there are more ranks than frames.
FrameRange block_of(FrameRange range, int rank, int size);

/// Starts MPI when this process was launched by mpirun (or srun) with more than one rank, as
/// the launcher's environment says (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK); ends it when
/// destroyed. Builds without MPI always run serially.
class Launch {
public:
    Launch(int& argc, char**& argv);
    ~Launch();
    Launch(const Launch&) = delete;
    Launch& operator=(const Launch&) = delete;

    /// After this rank's command returned `code` (2: it failed, its error already printed):
    /// combines every rank's code, assembles the outputs on rank 0 (text outputs gathered
    /// through MPI and concatenated in rank order; part recordings joined) and returns the
    /// run's exit code: 2 if a rank failed, else 130 or 143 if a rank
    /// was stopped by a signal, else the largest (1 when any block had collisions), returned
    /// by rank 0 (the others return 0: mpirun exits with the first non-zero code). Serially:
    /// `code`.
    int finish(int code);
};

/// True under mpirun with more than one rank.
bool parallel();
/// True serially and on rank 0: the process that prints the run's own lines (totals, notes)
/// and shows a progress bar.
bool leader();
/// A last step of the run on rank 0 (rank 0's `step` is kept, the others' ignored), run when
/// every rank finished its command without error or signal (exit 0 or 1) and its outputs were
/// assembled: e.g. encoding a clip from every rank's frames. It prints its own lines; its exit
/// code becomes the run's when larger, and an exception it throws becomes one error line and
/// exit 2. Serially it does nothing (the command does the work itself).
void when_done(std::function<int()> step);
/// A line the run prints once, from the sums over the ranks of `values`: under MPI rank 0
/// prints `line(sums)` on stderr (stdout: `on_stdout`) when every rank is done (only when every rank registered as
/// many values: a rank that failed did not), so a run prints one line where each rank would
/// print its own; serially it does nothing (the command prints its line itself). `line` runs
/// on rank 0 only, after every rank finished its command.
void summary_line(std::vector<double> values, std::function<std::string(const std::vector<double>& sums)> line,
                  bool on_stdout = false);
/// This rank's block of `range` (remembered for error lines); `range` serially.
FrameRange block(FrameRange range);
/// Where this rank writes a text output (--pairs, --stats) that the run delivers at `target`
/// (a file or "-" for stdout): `target` serially, else a file of this rank's in the temporary
/// directory, sent to rank 0 by MPI at the end (no shared file system needed).
std::string text_output(const std::string& target);
/// How rank 0 joins the ranks' part recordings (record --join).
enum class RecordingJoin {
    Virtual,  ///< `target` maps the parts' rows (virtual datasets); the parts are kept, they are the data
    Copy,     ///< `target` holds a copy of every row (self-contained); the parts are removed
};

/// Where this rank writes a recording the run delivers at `target`: `target` serially, else a
/// part file on a file system rank 0 can read, joined by rank 0 into `target`
/// (recorder/join.hpp) once every rank finished: `target`.parts/rank<R>.h5 for a virtual join
/// (kept: `target` reads them), `target`.rank<R>.h5 for a copying one (removed after the join).
std::string recording_output(const std::string& target, RecordingJoin join = RecordingJoin::Virtual);
/// The command reads and processes scene frame `frame` now (named in error lines); returns it.
std::uint32_t at_frame(std::uint32_t frame);
/// "rank 1 of 3, frames 30..59, at frame 42: " under MPI, "" serially: the start of this
/// rank's error lines.
std::string error_prefix();

}  // namespace collidescope::app::ranks
