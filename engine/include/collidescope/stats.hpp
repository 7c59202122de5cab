#pragma once
/// Per-frame statistics: what every stage did and what it cost.
///
/// Each stage fills its own fields; fields of stages a method does not run stay zero. The
/// recorder stores exactly these structs, the decision system reads them, and `check --stats`
/// prints them; nothing is measured twice.

#include "collidescope/gpu_cull.hpp"
#include "collidescope/step_stats.hpp"

#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <utility>

namespace collidescope {

/// Bits of AabbFrameInfo::rebuild_reasons (the same values as bvh::RebuildReason).
enum AabbRebuildReasonBit : std::uint8_t {
    k_rebuild_initial = 1,   ///< the object had no hierarchy yet
    k_rebuild_topology = 2,  ///< its triangles changed (always rebuilds)
    k_rebuild_thesis = 4,    ///< thesis 5.2.1 rule: detection time > 3/4 of a rebuild's time
    k_rebuild_quality = 8,   ///< SAH cost degraded past the limit since the last build
};

/// What the AABB hierarchies (Mode 1, method `aabb`) did in one frame, beyond the counts.
struct AabbFrameInfo {
    /// OR of the reasons of the rebuilds decided this frame (AabbRebuildReasonBit); 0: none.
    std::uint8_t rebuild_reasons = 0;
    std::uint32_t rebuilt_objects = 0;     ///< hierarchies built on the engine thread (ms.rebuild)
    std::uint32_t background_started = 0;  ///< rebuilds handed to the worker thread
    std::uint32_t background_swaps = 0;    ///< worker-built hierarchies swapped in (then refit)
    /// Tree quality: the largest, over the hierarchies used this frame, of SAH cost divided by
    /// the SAH cost right after that hierarchy's last build (1 = as built; larger = degraded),
    /// taken after this frame's refits and before any rebuild (what the policy judged).
    double tree_quality = 0;
};

/// "initial,topology,thesis,quality" for the set bits of `reasons` ("" for none).
inline std::string rebuild_reason_names(std::uint8_t reasons) {
    std::string names;
    const std::pair<std::uint8_t, const char*> bits[] = {{k_rebuild_initial, "initial"},
        {k_rebuild_topology, "topology"}, {k_rebuild_thesis, "thesis"}, {k_rebuild_quality, "quality"}};
    for (const auto& [bit, name] : bits) {
        if ((reasons & bit) == 0) continue;
        if (!names.empty()) names += ',';
        names += name;
    }
    return names;
}

/// Calls `visit(name, value, unit)` for every AabbFrameInfo field, in a fixed order (the
/// recorder stores one dataset per name).
template <class Visitor>
void for_each_aabb_value(const AabbFrameInfo& info, Visitor&& visit) {
    visit("rebuild_reasons", double(info.rebuild_reasons), "1");
    visit("rebuilt_objects", double(info.rebuilt_objects), "1");
    visit("background_started", double(info.background_started), "1");
    visit("background_swaps", double(info.background_swaps), "1");
    visit("tree_quality", info.tree_quality, "1");
}

/// What the decision system ran on a frame (DecisionInfo::action).
enum DecisionAction : std::uint8_t {
    k_action_aabb = 0,         ///< Perform AABB (Mode 1's hierarchies)
    k_action_gpu_plain = 1,    ///< Perform GPU 1: the GPU cull without its metrics (fixed views, fixed P)
    k_action_gpu_improved = 2, ///< Perform GPU 2: the improved GPU cull (view matrix, sort, adaptive P)
    k_action_sample_both = 3,  ///< AABB and GPU 1 both run and timed; the AABB's pairs are reported
    k_action_hybrid = 4,       ///< the AABB + GPU cull framework (thesis 4.3)
};

/// Why the decision system chose this frame's action (DecisionInfo::reason). Thesis steps are
/// those of Algorithm 4 (Mode 1) and Algorithm 5 (Mode 2).
enum DecisionReason : std::uint8_t {
    k_reason_initial_sample = 0,  ///< Alg. 4 (1)-(2): first frame, sample AABB_T and GPU_T
    k_reason_aabb_faster = 1,     ///< Alg. 4 (4): AABB_T < GPU_T, perform AABB
    k_reason_rebuild_in_thread = 2,  ///< Alg. 4 (5): AABB_T > GPU_T: rebuild in a thread, GPU serves
    k_reason_resample = 3,        ///< Alg. 4 (5): the rebuild finished; sample both again
    k_reason_gpu_still_faster = 4,   ///< Alg. 4 (6): GPU_T still below AABB_T after the rebuild: Mode 2
    k_reason_rebuild_too_slow = 5,   ///< Alg. 4 (7): AABB rebuild average > GPU_T: Mode 2
    k_reason_explore = 6,         ///< Alg. 4 (8): the exploration draw chose Mode 2
    k_reason_mode2 = 7,           ///< Alg. 5 (1)-(3): Mode 2 performs GPU 2
    k_reason_aabb_faster_again = 8,  ///< Alg. 5 (4)-(5): AABB_T < GPU_T: lower exploration, Mode 1
    k_reason_cost_cheapest = 9,   ///< cost policy: the cheapest predicted method
    k_reason_cost_probe = 10,     ///< cost policy: re-measures a method whose estimate is stale
};

/// Name of a DecisionReason ("aabb_faster", ...); "unknown" for other values.
inline const char* decision_reason_name(std::uint8_t reason) {
    static constexpr const char* k_names[] = {"initial_sample", "aabb_faster", "rebuild_in_thread", "resample",
        "gpu_still_faster", "rebuild_too_slow", "explore", "mode2", "aabb_faster_again", "cost_cheapest", "cost_probe"};
    return reason < std::size(k_names) ? k_names[reason] : "unknown";
}

/// Name of a DecisionAction ("aabb", "gpu1", "gpu2", "sample", "hybrid"); "unknown" otherwise.
inline const char* decision_action_name(std::uint8_t action) {
    static constexpr const char* k_names[] = {"aabb", "gpu1", "gpu2", "sample", "hybrid"};
    return action < std::size(k_names) ? k_names[action] : "unknown";
}

/// One frame's decision of the `adaptive` method (thesis 4.4, Tables 4.4 and 4.5): the mode in
/// force, what ran, why, and the inputs the policy judged, as they were when it decided.
/// Times not measured yet are NaN.
struct DecisionInfo {
    std::uint8_t policy = 0;  ///< an AdaptivePolicy's value (k_adaptive_policy_names: 0 thesis, 1 cost)
    std::uint8_t mode = 1;    ///< the mode this frame ran in: 1 or 2
    std::uint8_t action = 0;  ///< DecisionAction
    std::uint8_t reason = 0;  ///< DecisionReason
    bool switched = false;    ///< the mode differs from the previous frame's
    bool rebuilding = false;  ///< a hierarchy rebuild was in flight on the worker thread
    double aabb_ms = 0;       ///< AABB_T: the last measured AABB detection time
    double gpu_ms = 0;        ///< GPU_T: the last measured GPU detection time
    double hybrid_ms = 0;     ///< the last measured hybrid time (cost policy; NaN otherwise)
    double rebuild_avg_ms = 0;  ///< AABB Rebuild Average: mean hierarchy build time so far
    double exploration = 0;   ///< probability that explore() chooses Mode 2
    double draw = 0;          ///< the uniform draw explore() compared against (NaN: no draw)
};

/// Calls `visit(name, value, unit)` for every DecisionInfo field, in a fixed order (the
/// recorder stores one dataset per name).
template <class Visitor>
void for_each_decision_value(const DecisionInfo& info, Visitor&& visit) {
    visit("policy", double(info.policy), "1");
    visit("mode", double(info.mode), "1");
    visit("action", double(info.action), "1");
    visit("reason", double(info.reason), "1");
    visit("switched", info.switched ? 1.0 : 0.0, "1");
    visit("rebuilding", info.rebuilding ? 1.0 : 0.0, "1");
    visit("aabb_ms", info.aabb_ms, "ms");
    visit("gpu_ms", info.gpu_ms, "ms");
    visit("hybrid_ms", info.hybrid_ms, "ms");
    visit("rebuild_avg_ms", info.rebuild_avg_ms, "ms");
    visit("exploration", info.exploration, "1");
    visit("draw", info.draw, "1");
}

/// The quantities of the hybrid framework's analysis (thesis 4.3, Table 4.2, Equations
/// 4.11-4.17) for one frame of the `hybrid` method.
struct HybridFrameInfo {
    std::uint64_t a1 = 0;     ///< A1: AABB node tests of the first traversal
    std::uint64_t a2 = 0;     ///< A2: AABB node tests of the final traversal on the culled trees
    std::uint64_t tri_1 = 0;  ///< TRI_1: triangle pairs left after the AABB cull
    std::uint64_t tri_r = 0;  ///< TRI_R: triangles rendered by the GPU cull (the marked set)
    std::uint64_t tri_2 = 0;  ///< TRI_2: triangle pairs left after the AABB and GPU culls
    double a_i_ms = 0;        ///< A_I: measured ms per AABB node test
    double t_i_ms = 0;        ///< T_I: measured ms per triangle-triangle test
    /// O: measured GPU cull ms per rendered triangle (render + readback over TRI_R), the
    /// thesis's O under its assumption of one query per triangle; GpuFrameInfo::query_ms keeps
    /// the cost per occlusion query.
    double o_ms = 0;
    double unculled = 0;      ///< P_C: TRI_2 / TRI_1, the share the GPU left (1 when TRI_1 = 0)
    double pure_aabb_ms = 0;  ///< Equation 4.11 evaluated: A1·A_I + TRI_1·T_I
    double hybrid_ms = 0;     ///< Equation 4.12 evaluated: A1·A_I + TRI_R·O + A2·A_I + TRI_2·T_I
    double tri_1_needed = 0;  ///< Equation 4.17: TRI_1 needed for the hybrid to win at TRI_R = 1
    bool predicted_hybrid_wins = false;  ///< Inequality 4.16: TRI_1·T_I > TRI_R·O + P_C·TRI_1·T_I
};

/// Calls `visit(name, value, unit)` for every HybridFrameInfo field, in a fixed order.
template <class Visitor>
void for_each_hybrid_value(const HybridFrameInfo& info, Visitor&& visit) {
    visit("a1", double(info.a1), "1");
    visit("a2", double(info.a2), "1");
    visit("tri_1", double(info.tri_1), "1");
    visit("tri_r", double(info.tri_r), "1");
    visit("tri_2", double(info.tri_2), "1");
    visit("a_i_ms", info.a_i_ms, "ms");
    visit("t_i_ms", info.t_i_ms, "ms");
    visit("o_ms", info.o_ms, "ms");
    visit("unculled", info.unculled, "1");
    visit("pure_aabb_ms", info.pure_aabb_ms, "ms");
    visit("hybrid_ms", info.hybrid_ms, "ms");
    visit("tri_1_needed", info.tri_1_needed, "1");
    visit("predicted_hybrid_wins", info.predicted_hybrid_wins ? 1.0 : 0.0, "1");
}

/// Everything one frame reports: StepStats's stage times and counts, and what each method's
/// own parts did (the recorder, the replayer and the decision system read these).
struct FrameStats {
    std::uint32_t frame = 0;
    std::string method;  ///< the method that produced this frame's pairs
    StageTimes ms;
    FrameCounts counts;
    std::optional<AabbFrameInfo> aabb;  ///< set by the `aabb` method only
    std::optional<GpuFrameInfo> gpu;    ///< set by the GPU cull methods only
    std::optional<HybridFrameInfo> hybrid;  ///< set by the `hybrid` method (and adaptive when it runs it)
    std::optional<DecisionInfo> decision;   ///< set by the `adaptive` method only
};

}  // namespace collidescope
