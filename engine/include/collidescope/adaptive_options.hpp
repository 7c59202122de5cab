#pragma once
/// Options of the decision system (method `adaptive`; thesis 4.4; docs/decision.md).

#include <cstdint>

namespace collidescope {

/// Which policy chooses each frame's culling.
enum class AdaptivePolicy : std::uint8_t {
    Thesis,  ///< Algorithms 4 and 5 of the thesis: Mode 1 (AABB) and Mode 2 (GPU), exploration
    Cost,    ///< ours: per-method cost estimates (aabb, gpu, hybrid), cheapest wins, stale ones re-probed
};

/// Options of the `adaptive` method.
struct AdaptiveOptions {
    AdaptivePolicy policy = AdaptivePolicy::Cost;
    /// Thesis: the exploration probability at the start ("initially high", 4.4.2).
    double initial_exploration = 0.5;
    /// Thesis: what inc_explore adds in Mode 2 (capped at max_exploration).
    double exploration_step = 0.05;
    double max_exploration = 0.5;
    /// Cost: frames after which an estimate is stale and re-probed (doubles after each probe
    /// that lost, up to max_probe_interval).
    std::uint32_t probe_interval = 16;
    std::uint32_t max_probe_interval = 256;
    /// Cost: weight of a new measurement in an estimate (exponential moving average).
    double smoothing = 0.5;
    std::uint64_t seed = 1;  ///< seeds the exploration draws
};

}  // namespace collidescope
