// Comparing two recordings.

#include "collidescope/recorder/compare.hpp"

#include "collidescope/recorder/reader.hpp"

#include <algorithm>
#include <iterator>

namespace collidescope::recorder {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return (lower + upper) / 2;
}

// Matched rows (row in a, row in b) by scene frame number; both index lists increase.
std::vector<std::pair<std::uint64_t, std::uint64_t>> match_frames(const std::vector<std::uint32_t>& a,
                                                                   const std::vector<std::uint32_t>& b) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> matched;
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (a[i] == b[j]) matched.emplace_back(i++, j++);
        else if (a[i] < b[j]) ++i;
        else ++j;
    }
    return matched;
}

std::uint64_t count_difference(const std::vector<TrianglePair>& x, const std::vector<TrianglePair>& y) {
    std::vector<TrianglePair> only;
    std::set_difference(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(only));
    return only.size();
}

std::vector<StageComparison> compare_stages(const Recording& a, const Recording& b,
                                            const std::vector<std::pair<std::uint64_t, std::uint64_t>>& matched) {
    std::vector<StageComparison> out;
    const std::vector<Series<double>> stages_b = b.stage_ms();
    for (const Series<double>& stage_a : a.stage_ms()) {
        const auto stage_b = std::find_if(stages_b.begin(), stages_b.end(),
                                          [&](const Series<double>& s) { return s.name == stage_a.name; });
        if (stage_b == stages_b.end()) continue;
        StageComparison row{stage_a.name};
        std::vector<double> values_a, values_b;
        for (const auto& [ra, rb] : matched) {
            values_a.push_back(stage_a.values[ra]);
            values_b.push_back(stage_b->values[rb]);
            row.total_a += stage_a.values[ra];
            row.total_b += stage_b->values[rb];
        }
        row.median_a = median(std::move(values_a));
        row.median_b = median(std::move(values_b));
        out.push_back(row);
    }
    return out;
}

void compare_times(const Recording& a, const Recording& b,
                   const std::vector<std::pair<std::uint64_t, std::uint64_t>>& matched,
                   const std::vector<std::uint32_t>& frames_a, ComparisonReport& report) {
    report.both_timed = a.has_frame_times() && b.has_frame_times();
    if (!report.both_timed) return;
    const std::vector<double> times_a = a.frame_times();
    const std::vector<double> times_b = b.frame_times();
    for (const auto& [ra, rb] : matched) {
        if (times_a[ra] == times_b[rb]) continue;
        if (!report.first_time_difference) report.first_time_difference = frames_a[ra];
        ++report.time_differences;
    }
}

}  // namespace

ComparisonReport compare_recordings(const Recording& a, const Recording& b) {
    const std::vector<std::uint32_t> frames_a = a.frame_indices();
    const std::vector<std::uint32_t> frames_b = b.frame_indices();
    const auto matched = match_frames(frames_a, frames_b);
    ComparisonReport report;
    report.matched_frames = matched.size();
    report.frames_only_a = frames_a.size() - matched.size();
    report.frames_only_b = frames_b.size() - matched.size();
    for (const auto& [ra, rb] : matched) {
        const std::vector<TrianglePair> pairs_a = a.pairs(ra);
        const std::vector<TrianglePair> pairs_b = b.pairs(rb);
        if (pairs_a == pairs_b) continue;
        report.differences.push_back({frames_a[ra], count_difference(pairs_a, pairs_b), count_difference(pairs_b, pairs_a)});
    }
    report.stages = compare_stages(a, b, matched);
    compare_times(a, b, matched, frames_a, report);
    return report;
}

}  // namespace collidescope::recorder
