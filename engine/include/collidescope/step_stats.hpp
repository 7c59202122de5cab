#pragma once
/// The flat per-frame profile: what every stage cost and counted, the part of a frame's stats
/// that the embedding facade hands out (collidescope/session.hpp, Session::stats()). The
/// engine's FrameStats (collidescope/stats.hpp) holds these and what each method's own parts
/// did (hierarchies, GPU cull passes, decisions); `check --stats` and stats_json() print all.
///
/// Each stage fills its own fields; fields of stages a method does not run stay zero.

#include <cstdint>
#include <string>

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
    std::uint64_t exact_fallbacks = 0;   ///< predicate calls that needed expansions or GMP
    std::uint64_t colliding_pairs = 0;   ///< confirmed pairs
    std::uint64_t nodes_visited = 0;     ///< hierarchy node pairs tested + self nodes entered (Mode 1)
    std::uint64_t rebuilds = 0;          ///< hierarchies built this frame, engine thread or worker (Mode 1)
    std::uint64_t exact_shortcuts = 0;   ///< predicate calls the float filter left open and the
                                         ///< cheap exact stage decided (no expansions)
    /// Bytes of positions converted at the input boundary (Frame::positions_copied_bytes): 0
    /// when the embedding facade viewed the caller's packed doubles in place, V * 24 per
    /// object it converted (float32, strided); 0 for scenes read or generated.
    std::uint64_t positions_copied_bytes = 0;
    /// Triangles of self-collision objects whose own pairs the method proved apart without
    /// testing them (one-way normals and a simple contour, docs/explanation/algorithms.md; Mode 1 trees).
    std::uint64_t self_culled_triangles = 0;
    /// Box-overlapping pairs of one self-collision object that share a vertex index and that
    /// the traversal proved apart from their topology and one or two certified orient3d signs
    /// (docs/explanation/algorithms.md, "Adjacent pairs"): never candidates, so never exact tests (Mode 1
    /// trees and the GPU methods' final hierarchy).
    std::uint64_t adjacent_apart = 0;
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
    visit("exact_shortcuts", counts.exact_shortcuts);
    visit("positions_copied_bytes", counts.positions_copied_bytes);
    visit("self_culled_triangles", counts.self_culled_triangles);
    visit("adjacent_apart", counts.adjacent_apart);
}

/// One step's profile as the embedding facade reports it (every field a number or a name).
struct StepStats {
    std::uint32_t frame = 0;
    std::string method;  ///< the method that produced this frame's pairs
    StageTimes ms;
    FrameCounts counts;
};

}  // namespace collidescope
