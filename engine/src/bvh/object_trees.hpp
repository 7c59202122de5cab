#pragma once
// The `aabb` method's per-object trees across frames (engine/src/bvh, private): which tree
// each object has, for which topology, how good it still is, and the stages that keep them
// valid for a frame (swap, build, refit, policy). AabbCuller (aabb_culler.cpp) calls the stages in order.

#include "bvh/aabb_culler.hpp"
#include "bvh/background_rebuild.hpp"

#include "collidescope/scene.hpp"
#include "collidescope/stats.hpp"

#include <memory>
#include <span>
#include <vector>

namespace collidescope::bvh {

/// One object's tree and its history.
struct ObjectTree {
    Tree tree;
    std::shared_ptr<const Topology> topology;  ///< the topology the tree was built for; null: none
    double build_ms = 0;    ///< wall time of its last build
    double quality = 1;     ///< SAH cost / post-build cost after its last refit or build
    bool pending = false;   ///< a rebuild of it is in flight on the worker
    bool fitted = false;    ///< its boxes fit the current frame (built or refit this frame)
    bool fresh = false;     ///< built this frame (the policy leaves it alone)
    bool self = false;      ///< tested against itself this frame and surface-like: its tree carries surface patches
    std::uint64_t surface_revision = ~std::uint64_t{0};  ///< the topology `surface` was measured on
    bool surface = false;   ///< surface_like(its triangles), for surface_revision
    /// Frames in a row, up to this one, in which the object was in a pair with another one.
    std::uint32_t paired_frames = 0;
};

/// The trees of every object, kept across frames. Engine thread only.
class ObjectTrees {
public:
    explicit ObjectTrees(const AabbConfig& config);

    /// Marks every tree unfitted for a new frame, of whose objects `self` are tested against
    /// themselves (the surface-like ones' trees get surface patches).
    void begin_frame(const Frame& frame, std::span<const std::uint32_t> self);
    /// Installs finished worker trees whose topology is still current (wait: block for them).
    void swap_finished(const Frame& frame, bool wait, AabbFrameInfo& info);
    /// Builds the trees of `used` objects that have none or whose topology changed.
    void build_missing(const Frame& frame, std::span<const std::uint32_t> used, AabbFrameInfo& info);
    /// Refits the other `used` trees to the frame; returns the stage's milliseconds.
    void refit_rest(const Frame& frame, std::span<const std::uint32_t> used);
    /// Asks the policy about every refit tree (the last frame's detection and traversal
    /// times: RebuildInputs); rebuilds now or hands them to the worker.
    void apply_policy(const Frame& frame, std::span<const std::uint32_t> used, double detection_ms,
                      double traversal_ms, AabbFrameInfo& info);
    /// Counts the frames in a row each object has been in a pair with another (`paired`:
    /// this frame's), and fits the wide layouts (wide_tree.hpp) of those in such a pair for
    /// a second frame in a row, or whose layout refit kept fitted, in parallel. A contact of
    /// one frame does not pay for a layout: its first fit touches fresh memory, which cost
    /// more than the wide traversal saved on short contacts (spread frames of data sets A, B
    /// and D; records/2026-11-26-wide-traversal.md).
    void fit_wide(std::span<const std::uint32_t> paired);
    /// Hands every `objects` tree without a rebuild in flight to the worker (reason: the
    /// decision system's, recorded as k_rebuild_thesis). False when a batch is already in flight.
    bool start_rebuild(const Frame& frame, std::span<const std::uint32_t> objects, AabbFrameInfo& info);
    /// True while a worker batch runs or waits to be swapped in; finished: it waits.
    bool rebuild_in_flight() const { return m_background.busy(); }
    bool rebuild_finished() const { return m_background.ready(); }
    /// The views the traversal reads (indexed by object; only `used` objects are set).
    std::vector<MeshView> views(const Frame& frame, std::span<const std::uint32_t> used) const;
    const ObjectTree& at(std::uint32_t object) const { return m_trees[object]; }

private:
    void build(const Frame& frame, std::span<const std::uint32_t> objects);
    /// Starts the worker on `objects` (none pending, worker idle), recording them in `info`.
    void hand_to_worker(const Frame& frame, std::span<const std::uint32_t> objects, RebuildReason reason,
                        AabbFrameInfo& info);
    void notify(TreeEventKind kind, std::uint32_t object, const ObjectFrame& mesh) const;
    /// The build options for one object's tree.
    BuildConfig build_config(std::uint32_t object) const;

    const AabbConfig& m_config;
    RebuildPolicy m_policy;
    std::vector<ObjectTree> m_trees;
    BackgroundRebuild m_background;
    TreeBuilder m_builder;  ///< the engine thread's builds (working memory kept between them)
};

}  // namespace collidescope::bvh
