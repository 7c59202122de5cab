#pragma once
// The `adaptive` method (thesis 4.4; engine/src/methods): every frame, a policy of the decision
// system (thesis or cost, decision/policy.hpp) chooses between the AABB hierarchies (Mode 1), the GPU cull
// without and with its mechanisms (GPU 1 and GPU 2, Mode 2) and the hybrid framework; the
// methods share one set of AABB trees; rebuilds run in a thread while the GPU serves frames.
// Every decision, with its inputs, goes to stats.decision.

#include "decision/policy.hpp"

#include "collidescope/method.hpp"

#include <functional>
#include <optional>
#include <memory>

namespace collidescope {

/// What the adaptive method is made of beyond PipelineConfig (tests inject these).
struct AdaptiveParts {
    /// Milliseconds on a monotonic clock for the policy's measurements; empty: steady_clock.
    std::function<double()> clock_ms;
    /// Uniform draws in [0, 1) for exploration; empty: a generator seeded with options.seed.
    decision::Uniform uniform;
    /// The GPU prior of the cost policy; empty: measured on a synthetic scene at construction.
    std::optional<decision::GpuCostPrior> prior;
    /// Replaces the policy that config.adaptive.policy names (tests script decisions).
    std::function<std::unique_ptr<decision::Policy>()> policy;
    /// Pretend no GL context can be made (tests of the unavailable path).
    bool without_gpu = false;
    /// Join worker rebuilds at the next frame (bvh::BackgroundMode::NextFrame), so that what
    /// the policy learns of a rebuild in a thread does not depend on the worker's real speed
    /// (tests with a scripted clock: a long run must repeat decision for decision).
    bool join_rebuilds_next_frame = false;
};

/// Makes the `adaptive` method. Without a GL context it runs AABB only and says so in the
/// decisions (it does not fail).
std::unique_ptr<Method> make_adaptive_method(const PipelineConfig& config, AdaptiveParts parts = {});

}  // namespace collidescope
