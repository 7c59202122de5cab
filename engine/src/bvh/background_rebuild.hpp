#pragma once
// Rebuilds on a worker thread (engine/src/bvh; thesis contribution 3, 4.4.1: "we rebuild the
// AABB hierarchy in a thread" while frames keep being served). The worker builds from its own
// snapshot of each mesh, so it shares nothing with the engine thread but the future that
// hands the trees back.

#include "bvh/bvh.hpp"
#include "bvh/rebuild_policy.hpp"

#include "collidescope/scene.hpp"

#include <future>
#include <memory>
#include <optional>
#include <vector>

namespace collidescope::bvh {

/// One object's mesh to build a tree for: a snapshot, owned by the job.
struct RebuildJob {
    std::uint32_t object = 0;
    std::shared_ptr<const Topology> topology;
    std::vector<Vec3> vertices;  ///< a copy of the frame's positions
    std::uint32_t frame = 0;     ///< the frame the snapshot was taken at
    RebuildReason reason = RebuildReason::None;
    BuildConfig config;          ///< the build's options (surface patches or not)
};

/// A finished job: the tree fits job.vertices (the snapshot), not necessarily the current frame.
struct RebuiltTree {
    RebuildJob job;
    Tree tree;
    BuildStats stats;
};

/// At most one batch of jobs in flight. Used from one thread (the engine's); the worker only
/// touches the batch it was given.
class BackgroundRebuild {
public:
    BackgroundRebuild() = default;
    /// Waits for a batch still running (its trees are dropped).
    ~BackgroundRebuild();
    BackgroundRebuild(const BackgroundRebuild&) = delete;
    BackgroundRebuild& operator=(const BackgroundRebuild&) = delete;

    /// True while a batch is running or finished but not taken.
    bool busy() const { return m_result.valid(); }
    /// True when a batch has finished and waits to be taken.
    bool ready() const;
    /// Starts building `jobs` on a worker thread. Precondition: !busy().
    void start(std::vector<RebuildJob> jobs);
    /// The finished batch, or nothing when none is in flight or (without `wait`) it is still
    /// running. With `wait`, blocks until it finishes.
    std::optional<std::vector<RebuiltTree>> take(bool wait);

private:
    std::future<std::vector<RebuiltTree>> m_result;
};

}  // namespace collidescope::bvh
