// The sinks of `collidescope check`.

#include "check_sinks.hpp"

#include <nlohmann/json.hpp>

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

std::string format_ms(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", ms);
    return text;
}

}  // namespace

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

namespace {

// The GPU cull's trace of one frame: PCS sizes, per view and per pass.
nlohmann::ordered_json gpu_json(const GpuFrameInfo& info) {
    nlohmann::ordered_json gpu;
    gpu["renderer"] = info.renderer;
    gpu["pcs_objects"] = {info.pcs_objects_in, info.pcs_objects_out};
    gpu["pcs_triangles"] = {info.pcs_triangles_in, info.pcs_triangles_out};
    gpu["queries"] = info.queries;
    gpu["triangles_per_query"] = info.triangles_per_query;
    gpu["query_ms"] = info.query_ms;
    gpu["rebuild_ms_per_triangle"] = info.rebuild_ms_per_triangle;
    std::string chosen;
    for (const std::uint8_t view : info.chosen_views) chosen += "xyz"[view];
    gpu["chosen_views"] = chosen;
    gpu["view_matrix"] = info.view_matrix;
    nlohmann::ordered_json views = nlohmann::ordered_json::array();
    for (const GpuViewInfo& view : info.views) {
        views.push_back({{"level", view.level == 0 ? "objects" : "triangles"}, {"view", std::string(1, "xyz"[view.view])},
                         {"pcs_in", view.pcs_in}, {"pcs_out", view.pcs_out}});
    }
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const GpuPassInfo& pass : info.passes) {
        passes.push_back({{"level", pass.level == 0 ? "objects" : "triangles"},
                          {"view", std::string(1, "xyz"[pass.view])},
                          {"pass", pass.reverse != 0 ? "reverse" : "forward"},
                          {"tested", pass.items_tested}, {"hidden", pass.items_hidden},
                          {"queries", pass.queries}, {"samples_passed", pass.samples_passed},
                          {"triangles_per_query", pass.triangles_per_query}});
    }
    gpu["views"] = std::move(views);
    gpu["passes"] = std::move(passes);
    return gpu;
}

}  // namespace

void StatsWriter::on_frame(const FrameReport& report) {
    nlohmann::ordered_json line;
    line["frame"] = report.stats.frame;
    line["method"] = report.stats.method;
    nlohmann::ordered_json ms = nlohmann::ordered_json::object();
    for_each_stage(report.stats.ms, [&](const char* name, double value) { ms[name] = value; });
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for_each_count(report.stats.counts, [&](const char* name, std::uint64_t value) { counts[name] = value; });
    line["ms"] = std::move(ms);
    line["counts"] = std::move(counts);
    if (report.stats.gpu) line["gpu"] = gpu_json(*report.stats.gpu);
    if (report.stats.aabb) {
        const AabbFrameInfo& aabb = *report.stats.aabb;
        line["aabb"] = {{"rebuild_reasons", rebuild_reason_names(aabb.rebuild_reasons)},
                        {"rebuilt_objects", aabb.rebuilt_objects},
                        {"background_started", aabb.background_started},
                        {"background_swaps", aabb.background_swaps},
                        {"tree_quality", aabb.tree_quality}};
    }
    if (report.stats.hybrid) {
        nlohmann::ordered_json hybrid;
        for_each_hybrid_value(*report.stats.hybrid, [&](const char* name, double value, const char*) {
            hybrid[name] = value;
        });
        line["hybrid"] = std::move(hybrid);
    }
    if (report.stats.decision) {
        const DecisionInfo& decision = *report.stats.decision;
        nlohmann::ordered_json json;
        for_each_decision_value(decision, [&](const char* name, double value, const char*) { json[name] = value; });
        json["policy"] = decision.policy == 0 ? "thesis" : "cost";
        json["action"] = decision_action_name(decision.action);
        json["reason"] = decision_reason_name(decision.reason);
        line["decision"] = std::move(json);
    }
    m_out << line.dump() << '\n';
}

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

std::string SummaryPrinter::total_line() const {
    const std::string modes =
        m_mode_frames[1] + m_mode_frames[2] == 0
            ? std::string()
            : " (mode 1: " + std::to_string(m_mode_frames[1]) + " frames, mode 2: " + std::to_string(m_mode_frames[2]) +
                  " frames, " + std::to_string(m_switches) + " switches)";
    return "total: " + std::to_string(m_frames) + " frames, " + std::to_string(m_frames_colliding) +
           " with collisions, " + std::to_string(m_colliding_pairs) + " colliding pairs" + modes + ", " +
           format_ms(m_total_ms) + " ms";
}

}  // namespace collidescope::app
