#pragma once
// `collidescope bench`, the reporting part: frames.csv, summary.csv, the printed table, one
// SVG plot of time per frame per method for each scene (in the style of the thesis's Figures
// 5.6-5.13, drawn by bench/scripts/plot_bench.py) and an index.html that shows them.

#include "bench_run.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace collidescope::app {

/// One scene and method, summed over its frames.
struct BenchSummary {
    std::string scene;
    std::string preset;
    std::string method;
    std::uint32_t frames = 0;
    double median_ms = 0;       ///< median of the per-frame total
    double total_ms = 0;        ///< sum of the per-frame totals
    double ratio = 0;           ///< total_ms / the scene's fastest method's total_ms
    std::uint64_t colliding_pairs = 0;
    std::uint64_t candidate_pairs = 0;
    /// Adaptive methods (names starting "adaptive"): total_ms over the oracle-best, the sum
    /// over frames of the fastest fixed method's time on that frame (issue 7); 0 otherwise.
    double oracle_ratio = 0;
    std::uint32_t mode2_frames = 0;   ///< adaptive methods: frames run in Mode 2
    std::uint32_t hybrid_frames = 0;  ///< adaptive methods: frames the hybrid framework served
    std::uint32_t switches = 0;       ///< adaptive methods: mode changes
};

/// True for the methods that choose per frame (their rows get an oracle ratio).
inline bool is_adaptive_method(const std::string& method) { return method.rfind("adaptive", 0) == 0; }

/// Summaries of every scene and method, in run order.
std::vector<BenchSummary> summarize(const std::vector<BenchScene>& scenes);

/// frames.csv: scene, preset, method, frame, every stage's ms (`ms_<stage>`), every count, the
/// scene's triangles and the adaptive methods' decision ("mode 1", "hybrid", "mode 2"; empty
/// for the fixed methods).
void write_frames_csv(const std::filesystem::path& file, const std::vector<BenchScene>& scenes);

/// summary.csv: one row per BenchSummary.
void write_summary_csv(const std::filesystem::path& file, const std::vector<BenchSummary>& rows);

/// The summary as an aligned text table.
void print_table(std::ostream& out, const std::vector<BenchSummary>& rows);

/// The hybrid framework's analysis (thesis 4.3) on each scene where `hybrid` and `aabb` both
/// ran: the medians of the measured unit costs and counts (Equations 4.11-4.17), and on how
/// many frames Inequality 4.16 predicted the winner of hybrid against aabb. "" when none.
std::string hybrid_analysis(const std::vector<BenchScene>& scenes);

/// Draws every scene's plot from directory/frames.csv with bench/scripts/plot_bench.py
/// (matplotlib, run by /usr/bin/python3); throws InputError when it cannot.
void draw_plots(const std::filesystem::path& directory);

/// The file name of a scene's plot: "time_<scene>_<preset>.svg".
std::string plot_file_name(const BenchScene& scene);

/// index.html: the run's settings, the summary table and every plot.
void write_index_html(const std::filesystem::path& file, const std::vector<BenchScene>& scenes,
                      const std::vector<BenchSummary>& rows, const std::string& settings);

/// Writes `text` to `file`; throws InputError naming the file when it cannot.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace collidescope::app
