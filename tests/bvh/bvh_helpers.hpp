#pragma once
// Shared pieces of the bvh tests: extra scene builders (fractured topology, coincident and
// coplanar sheets, soups with degenerate triangles), a validating tree hook, and runs of a
// scene through a pipeline or a configured method.

#include "methods/aabb_method.hpp"
#include "support/scene_builders.hpp"
#include "bvh/validate_tree.hpp"

#include "collidescope/pipeline.hpp"
#include "collidescope/scene.hpp"

#include <memory>
#include <string>
#include <vector>

namespace collidescope::testing {

/// A scene whose objects change topology: a sheet that fractures into loose triangles
/// (each with its own vertices, some dropped) that drift apart and fall into a second sheet;
/// the fragments' triangle set changes again every few frames. Deterministic for a seed.
Scene fractured_scene(std::uint64_t seed, std::uint32_t frames = 8);

/// Coincident sheets (identical vertices, different objects), coplanar overlapping sheets,
/// and a soup with degenerate triangles (points, segments) on a coarse grid, moving a little.
Scene sheets_and_degenerates_scene(std::uint64_t seed, std::uint32_t frames = 4);

/// Collects validator failures from the aabb method's tree events (thread-safe enough: the
/// method calls hooks on its engine thread only).
struct TreeChecker {
    std::vector<std::string> failures;
    std::uint64_t builds = 0;
    std::uint64_t refits = 0;
    std::uint64_t swaps = 0;
    bvh::ValidateOptions options;

    /// A hook for AabbConfig::on_tree that validates every event's tree into this checker.
    std::function<void(const bvh::TreeEvent&)> hook();
};

/// All triangle pairs whose closed boxes overlap, by testing every pair: between `a` (object
/// 0) and `*b` (object 1), or i < j within `a` when `b` is null. Sorted.
std::vector<TrianglePair> box_pairs(const MeshData& a, const MeshData* b);

/// The pairs of every frame of `scene` from `method` (run directly with the object level),
/// plus its stats.
struct MethodRun {
    std::vector<std::vector<TrianglePair>> pairs;  ///< per frame, sorted
    std::vector<FrameStats> stats;                 ///< per frame
};
MethodRun run_method(Method& method, const std::vector<Frame>& frames, bool self_collision);

/// The same through a Pipeline with `threads` (brute reference runs use this).
MethodRun run_pipeline(const std::string& method, const std::vector<Frame>& frames, bool self_collision,
                       int threads);

}  // namespace collidescope::testing
