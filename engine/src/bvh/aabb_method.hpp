#pragma once
// The `aabb` method (Mode 1, thesis 4.4.1): per-object hierarchies, built when an object
// first appears or its topology changes, refit every frame, rebuilt by the rebuild policy
// (on the engine thread or a worker); tree-vs-tree and self traversal give candidate pairs
// for the shared exact narrow phase.

#include "bvh/bvh.hpp"
#include "bvh/rebuild_policy.hpp"
#include "bvh/traverse.hpp"

#include "collidescope/aabb_options.hpp"
#include "collidescope/pipeline.hpp"

#include <functional>
#include <memory>
#include <span>

namespace collidescope::bvh {

/// Where policy rebuilds run (builds for new objects and topology changes always run on the
/// engine thread: there is no valid tree to serve the frame with meanwhile).
enum class BackgroundMode : std::uint8_t {
    Off,        ///< on the engine thread, before the frame's traversal
    Async,      ///< on a worker; frames use the refit tree until the new one is swapped in
    NextFrame,  ///< on a worker, joined at the start of the next frame (deterministic; tests)
};

/// What happened to a tree, for AabbConfig::on_tree.
enum class TreeEventKind : std::uint8_t { Build, Refit, Swap };

/// A tree event: the tree and the mesh it fits (for a Swap, the worker's snapshot).
struct TreeEvent {
    TreeEventKind kind;
    std::uint32_t object;
    const Tree& tree;
    std::span<const TriIndices> triangles;
    std::span<const Vec3> vertices;
};

/// Options of the `aabb` method.
struct AabbConfig {
    BuildConfig build;            ///< builder (LBVH by default), leaf size, grains
    RebuildPolicyConfig policy;   ///< the quality rule by default
    TraversalConfig traversal;
    BackgroundMode background = BackgroundMode::Async;
    /// Milliseconds on a monotonic clock, for the stage times and the policy's timings;
    /// empty: std::chrono::steady_clock. Tests inject a scripted clock.
    std::function<double()> clock_ms;
    /// Called on the engine thread after every build, refit and swap (tests run the validator
    /// here); empty: nothing.
    std::function<void(const TreeEvent&)> on_tree;
};

/// Makes the `aabb` method.
std::unique_ptr<Method> make_aabb_method(AabbConfig config);

/// The configuration that `options` (the command line's, through PipelineConfig) describe.
AabbConfig aabb_config(const AabbOptions& options);

}  // namespace collidescope::bvh

namespace collidescope {

/// Makes the `aabb` method with the default configuration.
std::unique_ptr<Method> make_aabb_method();
/// Makes the `aabb` method as `options` say (the registry's entry).
std::unique_ptr<Method> make_aabb_method(const AabbOptions& options);

}  // namespace collidescope
