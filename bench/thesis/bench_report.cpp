// bench's CSV files, table and index page (bench_plot.cpp runs the plotting script).

#include "bench_report.hpp"

#include "collidescope/error.hpp"
#include "collidescope/stats.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <limits>
#include <sstream>

namespace collidescope::app {
namespace {

std::vector<std::string> stage_names() {
    std::vector<std::string> names;
    for_each_stage(StageTimes{}, [&](const char* name, double) { names.emplace_back(name); });
    return names;
}

std::string fixed(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

BenchSummary summarize_method(const BenchScene& scene, const std::string& method) {
    BenchSummary row{scene.name, scene.preset, method};
    std::vector<double> totals;
    const std::size_t colliding = count_index("colliding_pairs");
    const std::size_t candidates = count_index("candidate_pairs");
    for (const BenchFrame& frame : scene.frames) {
        if (frame.method != method) continue;
        totals.push_back(frame.total_ms());
        row.total_ms += frame.total_ms();
        row.colliding_pairs += frame.counts[colliding];
        row.candidate_pairs += frame.counts[candidates];
    }
    row.frames = static_cast<std::uint32_t>(totals.size());
    if (!totals.empty()) {
        std::sort(totals.begin(), totals.end());
        const std::size_t n = totals.size();
        row.median_ms = n % 2 == 1 ? totals[n / 2] : 0.5 * (totals[n / 2 - 1] + totals[n / 2]);
    }
    return row;
}

// The decision system's choice on an adaptive method's frame, as plot_bench.py reads it.
const char* decision_name(const BenchFrame& frame) {
    if (frame.mode == 0) return "";
    if (frame.mode == 2) return "mode 2";
    return frame.action == k_action_hybrid ? "hybrid" : "mode 1";
}

}  // namespace

std::vector<BenchSummary> summarize(const std::vector<BenchScene>& scenes) {
    std::vector<BenchSummary> rows;
    for (const BenchScene& scene : scenes) {
        const std::size_t first = rows.size();
        double fastest = std::numeric_limits<double>::infinity();
        for (const std::string& method : scene.methods) {
            rows.push_back(summarize_method(scene, method));
            fastest = std::min(fastest, rows.back().total_ms);
        }
        for (std::size_t i = first; i < rows.size(); ++i) {
            rows[i].ratio = fastest > 0 ? rows[i].total_ms / fastest : 1.0;
        }
        // The oracle-best: per frame, the fastest fixed method.
        std::map<std::uint32_t, double> best;
        for (const BenchFrame& frame : scene.frames) {
            if (is_adaptive_method(frame.method)) continue;
            auto [it, inserted] = best.try_emplace(frame.frame, frame.total_ms());
            if (!inserted) it->second = std::min(it->second, frame.total_ms());
        }
        double oracle = 0;
        for (const auto& [frame, ms] : best) oracle += ms;
        for (std::size_t i = first; i < rows.size(); ++i) {
            if (!is_adaptive_method(rows[i].method)) continue;
            rows[i].oracle_ratio = oracle > 0 ? rows[i].total_ms / oracle : 0;
            std::uint8_t last_mode = 0;
            for (const BenchFrame& frame : scene.frames) {
                if (frame.method != rows[i].method) continue;
                rows[i].mode2_frames += frame.mode == 2 ? 1 : 0;
                rows[i].hybrid_frames += frame.action == k_action_hybrid ? 1 : 0;
                rows[i].switches += last_mode != 0 && frame.mode != last_mode ? 1 : 0;
                last_mode = frame.mode;
            }
        }
    }
    return rows;
}

void write_text_file(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out.flush()) throw InputError(file.string() + ": cannot write the file");
}

void write_frames_csv(const std::filesystem::path& file, const std::vector<BenchScene>& scenes) {
    std::ostringstream out;
    out << "scene,preset,method,frame";
    for (const std::string& name : stage_names()) out << ",ms_" << name;
    for (const std::string& name : count_names()) out << ',' << name;
    out << ",triangles,decision\n";
    for (const BenchScene& scene : scenes) {
        for (const BenchFrame& frame : scene.frames) {
            out << scene.name << ',' << scene.preset << ',' << frame.method << ',' << frame.frame;
            for (const double ms : frame.ms) out << ',' << fixed(ms, 4);
            for (const std::uint64_t count : frame.counts) out << ',' << count;
            out << ',' << scene.triangles << ',' << decision_name(frame) << '\n';
        }
    }
    write_text_file(file, out.str());
}

void write_summary_csv(const std::filesystem::path& file, const std::vector<BenchSummary>& rows) {
    std::ostringstream out;
    out << "scene,preset,method,frames,median_ms,total_ms,ratio_to_fastest,colliding_pairs,"
           "candidate_pairs,oracle_ratio,mode2_frames,hybrid_frames,switches\n";
    for (const BenchSummary& row : rows) {
        out << row.scene << ',' << row.preset << ',' << row.method << ',' << row.frames << ','
            << fixed(row.median_ms, 4) << ',' << fixed(row.total_ms, 4) << ',' << fixed(row.ratio, 3)
            << ',' << row.colliding_pairs << ',' << row.candidate_pairs << ',' << fixed(row.oracle_ratio, 3) << ','
            << row.mode2_frames << ',' << row.hybrid_frames << ',' << row.switches << '\n';
    }
    write_text_file(file, out.str());
}

void print_table(std::ostream& out, const std::vector<BenchSummary>& rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%-12s %-16s %6s %11s %12s %9s %14s %9s %7s\n", "scene", "method",
                  "frames", "median ms", "total ms", "x fastest", "colliding", "x oracle", "mode 2");
    out << line;
    for (const BenchSummary& row : rows) {
        const std::string scene = row.scene + ":" + row.preset;
        char oracle[32] = "", mode2[32] = "";
        if (is_adaptive_method(row.method)) {
            std::snprintf(oracle, sizeof oracle, "%.3f", row.oracle_ratio);
            std::snprintf(mode2, sizeof mode2, "%.0f%%", row.frames ? 100.0 * row.mode2_frames / row.frames : 0.0);
        }
        std::snprintf(line, sizeof line, "%-12s %-16s %6u %11.3f %12.3f %9.2f %14llu %9s %7s\n",
                      scene.c_str(), row.method.c_str(), row.frames, row.median_ms, row.total_ms,
                      row.ratio, static_cast<unsigned long long>(row.colliding_pairs), oracle, mode2);
        out << line;
    }
}

std::string hybrid_analysis(const std::vector<BenchScene>& scenes) {
    std::vector<std::string> names;
    for_each_hybrid_value(HybridFrameInfo{}, [&](const char* name, double, const char*) { names.emplace_back(name); });
    const auto index = [&](const char* name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const auto median_of = [](std::vector<double> values) {
        if (values.empty()) return 0.0;
        std::sort(values.begin(), values.end());
        return values[values.size() / 2];
    };
    std::ostringstream out;
    for (const BenchScene& scene : scenes) {
        std::map<std::uint32_t, double> aabb_ms;
        for (const BenchFrame& frame : scene.frames) {
            if (frame.method == "aabb") aabb_ms[frame.frame] = frame.total_ms();
        }
        std::map<std::string, std::vector<double>> columns;
        std::uint32_t frames = 0, right = 0, predicted = 0, won = 0;
        for (const BenchFrame& frame : scene.frames) {
            if (frame.method != "hybrid" || frame.hybrid.size() != names.size() || !aabb_ms.count(frame.frame)) continue;
            for (const char* name : {"o_ms", "t_i_ms", "a1", "a2", "tri_1", "tri_r", "tri_2", "unculled"}) {
                columns[name].push_back(frame.hybrid[index(name)]);
            }
            const bool says = frame.hybrid[index("predicted_hybrid_wins")] != 0;
            const bool wins = frame.total_ms() < aabb_ms[frame.frame];
            ++frames;
            predicted += says ? 1 : 0;
            won += wins ? 1 : 0;
            right += says == wins ? 1 : 0;
        }
        if (frames == 0) continue;
        char line[512];
        std::snprintf(line, sizeof line,
                      "hybrid analysis %s:%s (medians): O %.4g ms/triangle, T_I %.3g ms, A1 %.0f, A2 %.0f, TRI_1 %.0f, "
                      "TRI_R %.0f, TRI_2 %.0f, unculled %.3f; inequality 4.16 predicted the winner (hybrid vs aabb) on "
                      "%u of %u frames (predicted hybrid %u, hybrid won %u)\n",
                      scene.name.c_str(), scene.preset.c_str(), median_of(columns["o_ms"]), median_of(columns["t_i_ms"]),
                      median_of(columns["a1"]), median_of(columns["a2"]), median_of(columns["tri_1"]),
                      median_of(columns["tri_r"]), median_of(columns["tri_2"]), median_of(columns["unculled"]), right,
                      frames, predicted, won);
        out << line;
    }
    return out.str();
}

std::string plot_file_name(const BenchScene& scene) {
    return "time_" + scene.name + "_" + scene.preset + ".svg";
}

void write_index_html(const std::filesystem::path& file, const std::vector<BenchScene>& scenes,
                      const std::vector<BenchSummary>& rows, const std::string& settings) {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>collidescope bench</title>\n"
           "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
           "td,th{border:1px solid #bbb;padding:2px 8px;text-align:right}"
           "td:first-child,td:nth-child(2){text-align:left}</style></head><body>\n"
           "<h1>collidescope bench</h1>\n<p>" << settings << "</p>\n"
           "<p>Times are the median over the repeats of each frame; every method returned the "
           "same pairs on every frame unless a mismatch is listed below.</p>\n<table>\n"
           "<tr><th>scene</th><th>method</th><th>frames</th><th>median ms</th><th>total ms</th>"
           "<th>x fastest</th><th>colliding pairs</th><th>x oracle</th><th>mode 2 frames</th></tr>\n";
    for (const BenchSummary& row : rows) {
        out << "<tr><td>" << row.scene << ':' << row.preset << "</td><td>" << row.method << "</td><td>"
            << row.frames << "</td><td>" << fixed(row.median_ms, 3) << "</td><td>"
            << fixed(row.total_ms, 3) << "</td><td>" << fixed(row.ratio, 2) << "</td><td>"
            << row.colliding_pairs << "</td><td>" << (is_adaptive_method(row.method) ? fixed(row.oracle_ratio, 3) : "")
            << "</td><td>" << (is_adaptive_method(row.method) ? std::to_string(row.mode2_frames) : "") << "</td></tr>\n";
    }
    out << "</table>\n";
    for (const BenchScene& scene : scenes) {
        for (const BenchMismatch& m : scene.mismatches) {
            out << "<p><b>mismatch</b>: " << scene.name << " frame " << m.frame << ": " << m.method
                << " misses " << m.missing << " and adds " << m.extra << " pairs of " << m.reference
                << "</p>\n";
        }
        out << "<h2>" << scene.name << " (" << scene.preset << ", " << scene.triangles
            << " triangles)</h2>\n<img src=\"" << plot_file_name(scene) << "\" alt=\"time per frame, "
            << scene.name << "\">\n";
    }
    out << "</body></html>\n";
    write_text_file(file, out.str());
}

}  // namespace collidescope::app
