// The sinks of `collidescope check`.

#include "check_sinks.hpp"

#include "collidescope/stats_json.hpp"

#include <charconv>
#include <cstdio>

namespace collidescope::app {
namespace {

// Appends `value` in decimal and then `separator`.
void append(std::string& line, std::uint32_t value, char separator) {
    char digits[16];
    const auto result = std::to_chars(digits, digits + sizeof digits, value);
    line.append(digits, result.ptr);
    line.push_back(separator);
}

}  // namespace

std::string format_ms(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", ms);
    return text;
}

void PairsWriter::on_frame(const FrameReport& report) {
    std::string lines;
    lines.reserve(report.colliding_pairs.size() * 24);
    for (const TrianglePair& pair : report.colliding_pairs) {
        append(lines, report.stats.frame, '\t');
        append(lines, pair.obj_a, '\t');
        append(lines, pair.tri_a, '\t');
        append(lines, pair.obj_b, '\t');
        append(lines, pair.tri_b, '\n');
    }
    m_out.write(lines.data(), static_cast<std::streamsize>(lines.size()));
}

void StatsWriter::on_frame(const FrameReport& report) { m_out << stats_json(report.stats) << '\n'; }

void SummaryPrinter::on_frame(const FrameReport& report) {
    const std::size_t pairs = report.colliding_pairs.size();
    ++m_frames;
    m_frames_colliding += pairs > 0 ? 1 : 0;
    m_colliding_pairs += pairs;
    m_total_ms += report.stats.ms.total;
    if (report.stats.decision) {
        ++m_mode_frames[report.stats.decision->mode == 2 ? 2 : 1];
        m_switches += report.stats.decision->switched ? 1 : 0;
    }
    if (m_quiet) return;
    m_progress.log("frame " + std::to_string(report.stats.frame) + ": " + std::to_string(pairs) +
                   " colliding pairs, " + format_ms(report.stats.ms.total) + " ms");
}

std::vector<double> SummaryPrinter::totals() const {
    return {double(m_frames),         double(m_frames_colliding), double(m_colliding_pairs), double(m_mode_frames[1]),
            double(m_mode_frames[2]), double(m_switches),         m_total_ms};
}

std::string SummaryPrinter::total_line() const { return total_line(totals()); }

std::string SummaryPrinter::total_line(const std::vector<double>& totals) {
    const auto count = [&](std::size_t k) { return std::to_string(static_cast<std::uint64_t>(totals[k])); };
    const std::string modes = totals[3] + totals[4] == 0 ? std::string()
                                                         : " (mode 1: " + count(3) + " frames, mode 2: " + count(4) +
                                                               " frames, " + count(5) + " switches)";
    return "total: " + count(0) + " frames, " + count(1) + " with collisions, " + count(2) + " colliding pairs" + modes +
           ", " + format_ms(totals[6]) + " ms";
}

}  // namespace collidescope::app
