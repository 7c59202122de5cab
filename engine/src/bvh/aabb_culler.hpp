#pragma once
// Mode 1's culling (thesis 4.4.1; engine/src/bvh, private): per-object hierarchies, built when
// an object first appears or its topology changes, refit every frame, rebuilt by the rebuild
// policy (on the engine thread or a worker); tree-vs-tree and self traversal give candidate
// pairs. No narrow phase: the methods (engine/src/methods) add it.

#include "bvh/bvh.hpp"
#include "bvh/rebuild_policy.hpp"
#include "bvh/traverse.hpp"

#include "collidescope/aabb_options.hpp"
#include "collidescope/frame_context.hpp"
#include "collidescope/stats.hpp"

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

/// Options of the AABB culling (the `aabb` method's, and the trees `hybrid` and `adaptive` share).
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

class ObjectTrees;

/// Mode 1's culling: the per-object trees kept across frames and the traversal. The `aabb`
/// method is this plus the narrow phase; `hybrid` and `adaptive` share one with the methods
/// they run, so the trees stay warm whichever of them serves a frame.
class AabbCuller {
public:
    explicit AabbCuller(AabbConfig config);
    ~AabbCuller();
    AabbCuller(const AabbCuller&) = delete;
    AabbCuller& operator=(const AabbCuller&) = delete;

    /// Swaps in finished worker trees, builds missing ones, refits the rest, asks the rebuild
    /// policy, then traverses: appends every candidate pair (canonical, unordered) and fills
    /// ms.rebuild/refit/traversal/cull, counts box_tests/candidate_pairs/nodes_visited/
    /// rebuilds and stats.aabb.
    TraversalStats cull(const FrameContext& context, std::vector<TrianglePair>& candidates, FrameStats& stats);
    /// The hybrid framework's final traversal (thesis 4.3, Figure 4.7 D): tree-vs-tree over
    /// the inter-object pairs of the last cull()'s frame (which must be `context`'s), on the
    /// trees culled by `alive` (per object, per triangle id: 1 survived; an empty entry: the
    /// object has no survivor). Appends the candidate pairs among the survivors.
    TraversalStats traverse_culled(const FrameContext& context, const std::vector<std::vector<std::uint8_t>>& alive,
                                   std::vector<TrianglePair>& candidates);
    /// The last frame's detection time (traversal + narrow phase: the thesis rebuild rule) and
    /// its traversal time alone (the quality rule's payback: what a better tree can shrink).
    void set_detection_ms(double detection_ms, double traversal_ms) {
        m_last_detection_ms = detection_ms;
        m_last_traversal_ms = traversal_ms;
    }
    /// Starts rebuilding, on the worker, every tree the last culled frame used, from `frame`'s
    /// positions (thesis Algorithm 4 step 5, "Rebuild In Thread"); the next cull() after it
    /// finished swaps them in and refits them to its frame. Records the start in `info`.
    /// False when a rebuild is already in flight or there is nothing to rebuild.
    bool start_rebuild(const Frame& frame, AabbFrameInfo& info);
    /// A worker rebuild is running, or finished and not yet swapped in.
    bool rebuild_in_flight() const;
    /// A worker rebuild finished and waits to be swapped in by the next cull(). Under
    /// BackgroundMode::NextFrame, any rebuild in flight counts as finished (the next cull()
    /// joins it), so that the answer does not depend on the worker's speed.
    bool rebuild_finished() const;
    /// The objects the last cull() used.
    const std::vector<std::uint32_t>& used() const { return m_used; }
    /// Milliseconds on the culler's clock (AabbConfig::clock_ms): the methods that share it
    /// time their narrow phase with it, so a scripted clock scripts the whole detection time.
    double now() const { return m_config.clock_ms(); }

private:
    AabbConfig m_config;
    std::unique_ptr<ObjectTrees> m_trees;
    std::shared_ptr<TraversalBuffers> m_buffers = make_traversal_buffers();
    std::vector<std::uint32_t> m_used;
    double m_last_detection_ms = 0;
    double m_last_traversal_ms = 0;
};

/// Whether rebuilds run on the worker thread under `mode` when frames use `threads` worker
/// threads (PipelineConfig::threads, 0 = all): AabbBackground::Auto is on only below TBB's
/// default concurrency (the hardware threads this process may use).
bool rebuild_in_background(AabbBackground mode, int threads);

/// The configuration that `options` (the command line's, through PipelineConfig) describe,
/// for frames on `threads` worker threads (0 = all).
AabbConfig aabb_config(const AabbOptions& options, int threads);

}  // namespace collidescope::bvh
