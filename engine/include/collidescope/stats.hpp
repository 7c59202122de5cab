#pragma once
/// Per-frame statistics: what every stage did and what it cost.
///
/// Each stage fills its own fields; fields of stages a method does not run stay zero. The
/// recorder stores exactly these structs, the decision system reads them, and `check --stats`
/// prints them; nothing is measured twice.

#include "collidescope/gpu_cull.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace collidescope {

/// Milliseconds per stage of one frame. `cull` is everything between the object level and
/// the narrow phase; refit/rebuild/traversal/gpu_* break it down for the methods that run them.
struct StageTimes {
    double update = 0;           ///< take the new positions, object boxes
    double object_level = 0;     ///< sweep and prune over object boxes
    double cull = 0;             ///< method's culling, total
    double refit = 0;            ///< AABB refit (Mode 1)
    double rebuild = 0;          ///< AABB build/rebuild on the engine thread
    double traversal = 0;        ///< tree-vs-tree and self traversal
    double gpu_render = 0;       ///< GPU cull passes (Mode 2)
    double gpu_readback = 0;     ///< reading query results / flags back
    double final_hierarchy = 0;  ///< hierarchy over the GPU survivors (thesis's R)
    double narrow = 0;           ///< exact triangle-triangle tests
    double total = 0;            ///< the whole frame
};

/// Counts of one frame.
struct FrameCounts {
    std::uint64_t triangles = 0;         ///< triangles in the frame, all objects
    std::uint64_t object_pairs = 0;      ///< object pairs whose boxes overlap (+ self objects)
    std::uint64_t box_tests = 0;         ///< triangle or node box tests by the method
    std::uint64_t candidate_pairs = 0;   ///< pairs that survived culling
    std::uint64_t exact_tests = 0;       ///< triangle-triangle tests run
    std::uint64_t exact_fallbacks = 0;   ///< predicate calls the float filter could not decide
    std::uint64_t colliding_pairs = 0;   ///< confirmed pairs
    std::uint64_t nodes_visited = 0;     ///< hierarchy node pairs tested + self nodes entered (Mode 1)
    std::uint64_t rebuilds = 0;          ///< hierarchies built this frame, engine thread or worker (Mode 1)
};

/// Calls `visit(name, milliseconds)` for every StageTimes field in declaration order. This
/// is the one list of stage names: `check --stats`, the recorder and the docs all use it.
template <class Visitor>
void for_each_stage(const StageTimes& ms, Visitor&& visit) {
    visit("update", ms.update);
    visit("object_level", ms.object_level);
    visit("cull", ms.cull);
    visit("refit", ms.refit);
    visit("rebuild", ms.rebuild);
    visit("traversal", ms.traversal);
    visit("gpu_render", ms.gpu_render);
    visit("gpu_readback", ms.gpu_readback);
    visit("final_hierarchy", ms.final_hierarchy);
    visit("narrow", ms.narrow);
    visit("total", ms.total);
}

/// Calls `visit(name, count)` for every FrameCounts field in declaration order (the one list
/// of count names, like for_each_stage).
template <class Visitor>
void for_each_count(const FrameCounts& counts, Visitor&& visit) {
    visit("triangles", counts.triangles);
    visit("object_pairs", counts.object_pairs);
    visit("box_tests", counts.box_tests);
    visit("candidate_pairs", counts.candidate_pairs);
    visit("exact_tests", counts.exact_tests);
    visit("exact_fallbacks", counts.exact_fallbacks);
    visit("colliding_pairs", counts.colliding_pairs);
    visit("nodes_visited", counts.nodes_visited);
    visit("rebuilds", counts.rebuilds);
}

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
        if ((reasons & bit) != 0) names += (names.empty() ? "" : ",") + std::string(name);
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

/// Everything one frame reports.
struct FrameStats {
    std::uint32_t frame = 0;
    std::string method;  ///< the method that produced this frame's pairs
    StageTimes ms;
    FrameCounts counts;
    std::optional<AabbFrameInfo> aabb;  ///< set by the `aabb` method only
    std::optional<GpuFrameInfo> gpu;    ///< set by the GPU cull methods only
};

}  // namespace collidescope
