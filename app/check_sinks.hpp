#pragma once
// The trace sinks of `collidescope check`: the pairs TSV, the stats JSON Lines and the
// per-frame summary on stderr. Each sees every frame once, in order, through the engine's
// TraceSink interface (the recorder of a later issue is one more sink).

#include "progress.hpp"

#include "collidescope/trace.hpp"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace collidescope::app {

/// `--pairs`: one line per colliding pair, `frame\tobjA\ttriA\tobjB\ttriB`, in the engine's
/// sorted order, so the whole file is sorted numerically when frames come in order.
class PairsWriter final : public TraceSink {
public:
    explicit PairsWriter(std::ostream& out) : m_out(out) {}
    void on_frame(const FrameReport& report) override;

private:
    std::ostream& m_out;
};

/// `--stats`: JSON Lines, one object per frame:
/// {"frame", "method", "ms": {every StageTimes field}, "counts": {every FrameCounts field}}.
class StatsWriter final : public TraceSink {
public:
    explicit StatsWriter(std::ostream& out) : m_out(out) {}
    void on_frame(const FrameReport& report) override;

private:
    std::ostream& m_out;
};

/// One line per frame on stderr ("frame 12: 3 colliding pairs, 1.234 ms"), unless quiet, and
/// the totals for the final line.
class SummaryPrinter final : public TraceSink {
public:
    SummaryPrinter(Progress& progress, bool quiet) : m_progress(progress), m_quiet(quiet) {}
    void on_frame(const FrameReport& report) override;

    /// "total: 60 frames, 36 with collisions, 1234 colliding pairs, 123.456 ms"; the adaptive
    /// method adds " (mode 1: 58 frames, mode 2: 2 frames, 2 switches)" before the time.
    std::string total_line() const;
    std::uint64_t colliding_pairs() const { return m_colliding_pairs; }
    /// The counts and the time behind total_line(), as numbers that add up over runs of
    /// disjoint frames (the ranks of an MPI run: ranks::summary_line).
    std::vector<double> totals() const;
    /// total_line() of `totals` (the sums of several runs' totals()).
    static std::string total_line(const std::vector<double>& totals);

private:
    Progress& m_progress;
    bool m_quiet;
    std::uint64_t m_frames = 0;
    std::uint64_t m_frames_colliding = 0;
    std::uint64_t m_colliding_pairs = 0;
    double m_total_ms = 0;
    std::uint64_t m_mode_frames[3] = {0, 0, 0};  ///< frames per mode (adaptive), [0] unused
    std::uint64_t m_switches = 0;
};

/// Milliseconds with three decimals, as the summary lines and `inspect` print them.
std::string format_ms(double ms);

}  // namespace collidescope::app
