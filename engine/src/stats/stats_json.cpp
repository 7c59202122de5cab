// stats_json: FrameStats -> the JSON object of `check --stats`.

#include "collidescope/stats_json.hpp"

#include "collidescope/adaptive_options.hpp"

#include <nlohmann/json.hpp>

namespace collidescope {
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

nlohmann::ordered_json aabb_json(const AabbFrameInfo& aabb) {
    return {{"rebuild_reasons", rebuild_reason_names(aabb.rebuild_reasons)},
            {"rebuilt_objects", aabb.rebuilt_objects},
            {"background_started", aabb.background_started},
            {"background_swaps", aabb.background_swaps},
            {"tree_quality", aabb.tree_quality}};
}

nlohmann::ordered_json hybrid_json(const HybridFrameInfo& info) {
    nlohmann::ordered_json hybrid;
    for_each_hybrid_value(info, [&](const char* name, double value, const char*) { hybrid[name] = value; });
    return hybrid;
}

nlohmann::ordered_json decision_json(const DecisionInfo& decision) {
    nlohmann::ordered_json json;
    for_each_decision_value(decision, [&](const char* name, double value, const char*) { json[name] = value; });
    json["policy"] = option_name(k_adaptive_policy_names, static_cast<AdaptivePolicy>(decision.policy));
    json["action"] = decision_action_name(decision.action);
    json["reason"] = decision_reason_name(decision.reason);
    return json;
}

}  // namespace

std::string stats_json(const FrameStats& stats) {
    nlohmann::ordered_json line;
    line["frame"] = stats.frame;
    line["method"] = stats.method;
    nlohmann::ordered_json ms = nlohmann::ordered_json::object();
    for_each_stage(stats.ms, [&](const char* name, double value) { ms[name] = value; });
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for_each_count(stats.counts, [&](const char* name, std::uint64_t value) { counts[name] = value; });
    line["ms"] = std::move(ms);
    line["counts"] = std::move(counts);
    if (stats.gpu) line["gpu"] = gpu_json(*stats.gpu);
    if (stats.aabb) line["aabb"] = aabb_json(*stats.aabb);
    if (stats.hybrid) line["hybrid"] = hybrid_json(*stats.hybrid);
    if (stats.decision) line["decision"] = decision_json(*stats.decision);
    return line.dump();
}

}  // namespace collidescope
