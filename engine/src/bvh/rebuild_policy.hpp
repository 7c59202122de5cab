#pragma once
// The rebuild policy (engine/src/bvh): when a refit tree should be built again. A pure
// function of what the method measured (its timings come from the method's injected clock),
// so tests script the timings and assert each decision.

#include "collidescope/aabb_options.hpp"
#include "collidescope/stats.hpp"

#include <cstdint>
#include <string_view>

namespace collidescope::bvh {

/// Why a tree was (re)built. The values are the bits of AabbFrameInfo::rebuild_reasons,
/// defined once in collidescope/stats.hpp.
enum class RebuildReason : std::uint8_t {
    None = 0,
    Initial = k_rebuild_initial,    ///< the object had no tree yet
    Topology = k_rebuild_topology,  ///< its triangles changed (always rebuilds)
    Thesis = k_rebuild_thesis,      ///< thesis 5.2.1: detection time above 3/4 of a rebuild's time
    Quality = k_rebuild_quality,    ///< the refit tree's SAH cost degraded past the limit
};

/// "none", "initial", "topology", "thesis" or "quality".
std::string_view rebuild_reason_name(RebuildReason reason);

/// Which rule decides rebuilds of trees whose topology did not change: Quality (SAH cost /
/// post-build cost above quality_limit), Thesis (the last frame's detection time above
/// thesis_fraction * rebuild time) or Never (refit only; topology changes still rebuild). One
/// definition: the public option, AabbRebuildRule (collidescope/aabb_options.hpp).
using RebuildRule = AabbRebuildRule;

/// Options of the policy.
struct RebuildPolicyConfig {
    RebuildRule rule = RebuildRule::Quality;
    /// Thesis 5.2.1: "rebuilds after the collision detection time becomes more expensive than
    /// three fourths of a rebuild".
    double thesis_fraction = 0.75;
    /// Quality rule: rebuild when the refit tree's SAH cost exceeds this multiple of its cost
    /// right after its build...
    double quality_limit = 1.5;
    /// ...and the rebuild pays for itself within this many frames: what a frame's traversal
    /// could save, traversal_ms * (1 - 1 / quality) (a tree of SAH cost `quality` times its
    /// built cost against one of cost 1; the narrow phase tests the same candidates either
    /// way), times payback_frames, reaches rebuild_ms. Past in_frame_quality the tree is
    /// rebuilt whatever the times. 0: the SAH cost alone decides. Without it a 437k-triangle
    /// cloth (cloth-drape:large, 2 threads) spent 110-160 ms rebuilding in one frame to save
    /// under a millisecond a frame (records/2026-11-26-large-blocks.md).
    double payback_frames = 16;
    /// A chosen rebuild runs in the frame, even where rebuilds go to the background worker,
    /// when the refit tree's SAH cost is past this multiple of its post-build cost: the frame
    /// would traverse a tree that costs far more than its build (data set D's jump from frame
    /// 0 to frame 49: quality 52.7, a 2.8 s traversal against a 12.6 ms build).
    double in_frame_quality = 4;
};

/// What the policy sees for one object's tree after this frame's refit.
struct RebuildInputs {
    bool has_tree = false;          ///< a tree exists for this object
    bool topology_changed = false;  ///< the frame's triangles differ from the tree's
    double quality = 1;             ///< refit SAH cost / post-build SAH cost
    /// The last frame's collision detection time over the hierarchies (traversal + narrow
    /// phase, ms): what the thesis calls the collision detection time.
    double detection_ms = 0;
    /// What rebuilding costs (ms): the last measured build time of the hierarchies in use.
    double rebuild_ms = 0;
    /// The last frame's traversal time alone (ms): the part of detection_ms a better tree
    /// shrinks (the narrow phase tests the same candidates whatever the tree).
    double traversal_ms = 0;
};

/// Decides, per tree and frame, whether to rebuild and why.
class RebuildPolicy {
public:
    explicit RebuildPolicy(RebuildPolicyConfig config = {}) : m_config(config) {}
    /// None: keep the refit tree. Initial and Topology take precedence over the rule.
    RebuildReason decide(const RebuildInputs& inputs) const;
    const RebuildPolicyConfig& config() const { return m_config; }

private:
    /// The quality rule: degraded past quality_limit, and the rebuild pays (payback_frames).
    bool quality_rebuild_pays(const RebuildInputs& inputs) const;

    RebuildPolicyConfig m_config;
};

}  // namespace collidescope::bvh
