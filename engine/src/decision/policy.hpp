#pragma once
// The decision system's policies (engine/src/decision, private; thesis 4.4, Algorithms 4 and
// 5; docs/explanation/decision.md). A policy is a pure function of what the adaptive method measured: it
// sees the facts of a frame before it runs, says what to run, and then observes the measured
// times. No clock, no GL, no threads in here: the random draws come from an injected source,
// so tests walk a policy through every branch with scripted times and draws.

#include "collidescope/adaptive_options.hpp"
#include "collidescope/stats.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

namespace collidescope::decision {

/// What the adaptive method can run on a frame (the values of DecisionAction).
enum class Action : std::uint8_t {
    Aabb = k_action_aabb,                ///< Perform AABB
    GpuPlain = k_action_gpu_plain,       ///< Perform GPU 1 (no metrics: fixed views and P)
    GpuImproved = k_action_gpu_improved, ///< Perform GPU 2 (the improved cull of 4.2)
    SampleBoth = k_action_sample_both,   ///< Perform AABB and Perform GPU 1, both timed
    Hybrid = k_action_hybrid,            ///< the AABB + GPU cull framework (4.3)
};

inline constexpr double k_unmeasured = std::numeric_limits<double>::quiet_NaN();

/// What the method knows of a frame before running it.
struct FrameFacts {
    bool gpu_available = true;       ///< a GL context exists (else only Aabb may be chosen)
    bool rebuild_running = false;    ///< a worker rebuild is in flight and not finished
    bool rebuild_finished = false;   ///< a worker rebuild finished, to be swapped in next AABB run
    double rebuild_average_ms = 0;   ///< AABB Rebuild Average (Table 4.4)
    std::uint64_t pcs_triangles = 0; ///< triangles of the objects in inter-object pairs
    /// What the hybrid framework would render (TRI_R), estimated from the last AABB run:
    /// at most two triangles per inter-object candidate pair, at most pcs_triangles.
    std::uint64_t marked_triangles = 0;
};

/// What to do on a frame.
struct Decision {
    Action action = Action::Aabb;
    std::uint8_t reason = k_reason_aabb_faster;  ///< DecisionReason
    std::uint8_t mode = 1;                       ///< the mode this frame runs in
    bool start_rebuild = false;                  ///< Rebuild In Thread before running
    double draw = k_unmeasured;                  ///< the exploration draw, when one was made
    bool calibrate = false;                      ///< measure the GPU prior (set_gpu_prior) this frame
};

/// What a frame measured: detection times (ms) of what ran; NaN for what did not.
struct Outcome {
    double aabb_ms = k_unmeasured;
    double gpu_ms = k_unmeasured;     ///< GPU 1 or GPU 2, whichever ran
    double hybrid_ms = k_unmeasured;
    /// Total ms of the frame (everything the method did), for the cost policy's budget.
    double frame_ms = 0;
};

/// A prior of the GPU cull's cost: ms = fixed_ms + per_triangle_ms * PCS triangles (the
/// adaptive method measures it on a synthetic scene when the cost policy asks, inside a frame).
struct GpuCostPrior {
    double fixed_ms = 0;
    double per_triangle_ms = 0;
};

/// A policy: decide, then observe, once per frame, in that order.
class Policy {
public:
    virtual ~Policy() = default;
    virtual Decision decide(const FrameFacts& facts) = 0;
    virtual void observe(const Outcome& outcome) = 0;
    /// The policy's inputs as the trace shows them (times, exploration); the method fills
    /// mode, action, reason, switched, rebuilding and draw from the Decision.
    virtual DecisionInfo inputs() const = 0;
    /// Hands over the GPU prior once it is measured (the cost policy needs it before it
    /// considers the GPU; the thesis's ignores it).
    virtual void set_gpu_prior(const GpuCostPrior&) {}
};

/// A uniform draw in [0, 1).
using Uniform = std::function<double()>;

/// Algorithms 4 and 5 of the thesis.
std::unique_ptr<Policy> make_thesis_policy(const AdaptiveOptions& options, Uniform uniform);

/// Ours: the cheapest estimate runs; the others are re-probed within a time budget.
/// Until it has a prior (here or through set_gpu_prior), it treats the GPU as unavailable, and
/// asks for one (Decision::calibrate) once the run is long enough to afford it.
std::unique_ptr<Policy> make_cost_policy(const AdaptiveOptions& options, std::optional<GpuCostPrior> prior);

}  // namespace collidescope::decision
