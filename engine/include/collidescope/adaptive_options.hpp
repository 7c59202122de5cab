#pragma once
/// Options of the decision system (method `adaptive`; thesis 4.4; docs/explanation/decision.md).

#include "collidescope/option_names.hpp"

#include <cstdint>

namespace collidescope {

/// Which policy chooses each frame's culling.
enum class AdaptivePolicy : std::uint8_t {
    Thesis,  ///< Algorithms 4 and 5 of the thesis: Mode 1 (AABB) and Mode 2 (GPU), exploration
    Cost,    ///< ours: per-method cost estimates (aabb, gpu, hybrid), cheapest wins, stale ones re-probed
};

/// The names of AdaptivePolicy (--policy; the "policy" of check --stats, whose number is the
/// enumerator's value).
inline constexpr OptionNames<AdaptivePolicy, 2> k_adaptive_policy_names{
    {{"thesis", AdaptivePolicy::Thesis}, {"cost", AdaptivePolicy::Cost}}};

/// Options of the `adaptive` method.
struct AdaptiveOptions {
    AdaptivePolicy policy = AdaptivePolicy::Cost;
    /// Thesis: the exploration probability at the start ("initially high", 4.4.2).
    double initial_exploration = 0.5;
    /// Thesis: what inc_explore adds in Mode 2 (capped at max_exploration).
    double exploration_step = 0.05;
    double max_exploration = 0.5;
    /// Cost: the share of the run's time that probing each non-chosen method may cost: a
    /// method is re-measured once probe_budget x (ms since it last ran) exceeds what running
    /// it instead of the cheapest is predicted to cost extra.
    double probe_budget = 0.03;
    /// Cost: weight of a new measurement in an estimate (exponential moving average).
    double smoothing = 0.5;
    /// Cost: what the policy expects measuring the GPU prior to cost (ms). The measurement runs
    /// inside a frame once probe_budget x (ms of the run so far) reaches this, so short runs
    /// never pay for it.
    double calibration_ms = 100;
    /// Cost: whether the hybrid framework is among the candidates.
    bool use_hybrid = true;
    std::uint64_t seed = 1;  ///< seeds the exploration draws
};

}  // namespace collidescope
