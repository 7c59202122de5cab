// The overlay's lines of text (overlay_text.hpp).

#include "overlay_text.hpp"

#include "collidescope/adaptive_options.hpp"
#include "collidescope/stats.hpp"

#include <cmath>
#include <cstdio>

namespace collidescope::replays {
namespace {

std::string printf_text(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// The name of a recorded decision's policy (an AdaptivePolicy's value).
std::string policy_name(double value) {
    if (!std::isfinite(value)) return "unknown";
    return std::string(option_name(k_adaptive_policy_names, static_cast<AdaptivePolicy>(static_cast<int>(value))));
}

}  // namespace

std::string measured(const char* pattern, double value, const char* missing) {
    return std::isfinite(value) ? printf_text(pattern, value) : std::string(missing);
}

std::vector<std::string> decision_text(const FrameData& frame) {
    if (frame.decision.empty() || !std::isfinite(value_of(frame.decision, "action"))) {
        return {"not recorded (method " + frame.method + "; record --method adaptive)"};
    }
    const auto action = std::uint8_t(value_of(frame.decision, "action"));
    const auto reason = std::uint8_t(value_of(frame.decision, "reason"));
    std::string ran = std::string("ran ") + decision_action_name(action) + ": " + decision_reason_name(reason);
    if (value_of(frame.decision, "switched") == 1) ran += ", switched";
    if (value_of(frame.decision, "rebuilding") == 1) ran += ", rebuild in flight";
    return {
        ran,
        "AABB_T " + measured("%.3g ms", value_of(frame.decision, "aabb_ms")) + "  GPU_T " +
            measured("%.3g ms", value_of(frame.decision, "gpu_ms")) + "  hybrid " +
            measured("%.3g ms", value_of(frame.decision, "hybrid_ms")),
        "rebuild average " + measured("%.3g ms", value_of(frame.decision, "rebuild_avg_ms"), "none yet") + "  (" +
            policy_name(value_of(frame.decision, "policy")) + " policy)",
        "exploration " + measured("%.3f", value_of(frame.decision, "exploration"), "none") + "  draw " +
            measured("%.3f", value_of(frame.decision, "draw"), "none"),
    };
}

std::optional<std::string> aabb_text(const FrameData& frame) {
    const double rebuilt = value_of(frame.aabb, "rebuilt_objects");
    if (!std::isfinite(rebuilt)) return std::nullopt;
    const double reason_bits = value_of(frame.aabb, "rebuild_reasons");
    const std::string reasons = std::isfinite(reason_bits) ? rebuild_reason_names(std::uint8_t(reason_bits)) : "";
    return "AABB: rebuilt " + printf_text("%.0f", rebuilt) + " (" + (reasons.empty() ? "no rebuild" : reasons) +
           "), tree quality " + measured("%.2f", value_of(frame.aabb, "tree_quality"), "unknown");
}

std::optional<std::string> hybrid_text(const FrameData& frame) {
    const double tri_1 = value_of(frame.hybrid, "tri_1");
    if (!std::isfinite(tri_1)) return std::nullopt;
    return "hybrid: TRI_1 " + printf_text("%.0f", tri_1) + "  TRI_R " + measured("%.0f", value_of(frame.hybrid, "tri_r"), "-") +
           "  TRI_2 " + measured("%.0f", value_of(frame.hybrid, "tri_2"), "-");
}

std::string gpu_queries_text(const FrameData& frame) {
    return "queries " + measured("%.0f", value_of(frame.gpu, "queries"), "-") + "   P " +
           measured("%.0f", value_of(frame.gpu, "triangles_per_query"), "-") + " tris/query   O " +
           measured("%.3g ms", value_of(frame.gpu, "query_ms"), "not measured");
}

}  // namespace collidescope::replays
