// Algorithms 4 and 5 of the thesis (4.4) as a state machine over measured times.
//
// Readings of the extracted text (docs/explanation/decision.md):
// - Mode 1 checks (4) and (5) every frame against the last GPU_T; (7) and (8) are checked on
//   every Mode 1 frame that AABB serves; (6) only after a rebuild in a thread finished.
// - While the rebuild runs, GPU 1 serves the frames ("Rebuild In Thread() AND Perform GPU 1()").
// - Mode 2 raises exploration by exploration_step every frame (capped), performs GPU 2 and
//   returns to Mode 1 when the last AABB_T is below GPU_T, multiplying exploration by
//   AABB_T / GPU_T ("decrease exploration at rate of GPU_T / AABB_T").
// - A tie (AABB_T == GPU_T) counts as AABB faster in Mode 1 and keeps Mode 2 in Mode 2.

#include "decision/policy.hpp"

#include <algorithm>
#include <optional>

namespace collidescope::decision {
namespace {

enum class Phase : std::uint8_t { Start, Mode1, Rebuilding, Mode2 };

class ThesisPolicy final : public Policy {
public:
    ThesisPolicy(const AdaptiveOptions& options, Uniform uniform)
        : m_options(options), m_uniform(std::move(uniform)), m_exploration(options.initial_exploration) {}

    Decision decide(const FrameFacts& facts) override {
        if (!facts.gpu_available) return {Action::Aabb, k_reason_aabb_faster, 1};
        m_rebuild_average = facts.rebuild_average_ms;
        switch (m_phase) {
        case Phase::Start:  // (1), (2): sample both
            return {Action::SampleBoth, k_reason_initial_sample, 1};
        case Phase::Rebuilding:
            if (facts.rebuild_running) return {Action::GpuPlain, k_reason_rebuild_in_thread, 1};
            return {Action::SampleBoth, k_reason_resample, 1};  // (5): the rebuild finished
        case Phase::Mode2:
            m_exploration = std::min(m_options.max_exploration, m_exploration + m_options.exploration_step);  // (2)
            return {Action::GpuImproved, take_reason(k_reason_mode2), 2};  // (3)
        case Phase::Mode1:
            break;
        }
        if (m_aabb > m_gpu) {  // (5): GPU faster: rebuild in a thread, GPU 1 serves meanwhile
            m_phase = Phase::Rebuilding;
            Decision decision{Action::GpuPlain, k_reason_rebuild_in_thread, 1};
            decision.start_rebuild = true;
            return decision;
        }
        if (m_rebuild_average > m_gpu) return enter_mode2(k_reason_rebuild_too_slow, k_unmeasured);  // (7)
        const double draw = m_uniform();
        if (draw < m_exploration) return enter_mode2(k_reason_explore, draw);  // (8)
        Decision decision{Action::Aabb, take_reason(k_reason_aabb_faster), 1};  // (4)
        decision.draw = draw;
        return decision;
    }

    void observe(const Outcome& outcome) override {
        if (!std::isnan(outcome.aabb_ms)) m_aabb = outcome.aabb_ms;
        if (!std::isnan(outcome.gpu_ms)) m_gpu = outcome.gpu_ms;
        switch (m_phase) {
        case Phase::Start:
            m_phase = Phase::Mode1;
            break;
        case Phase::Rebuilding:
            if (!std::isnan(outcome.aabb_ms)) {  // the resample ran: (6)
                if (m_aabb > m_gpu) {
                    m_phase = Phase::Mode2;
                    m_next_reason = k_reason_gpu_still_faster;
                } else {
                    m_phase = Phase::Mode1;
                }
            }
            break;
        case Phase::Mode2:
            if (m_aabb < m_gpu) {  // (4), (5) of Algorithm 5
                m_exploration *= m_aabb / m_gpu;
                m_phase = Phase::Mode1;
                m_next_reason = k_reason_aabb_faster_again;
            }
            break;
        case Phase::Mode1:
            break;
        }
    }

    DecisionInfo inputs() const override {
        DecisionInfo info;
        info.policy = 0;
        info.aabb_ms = m_aabb;
        info.gpu_ms = m_gpu;
        info.hybrid_ms = k_unmeasured;
        info.rebuild_avg_ms = m_rebuild_average;
        info.exploration = m_exploration;
        return info;
    }

private:
    Decision enter_mode2(std::uint8_t reason, double draw) {
        m_phase = Phase::Mode2;
        m_exploration = std::min(m_options.max_exploration, m_exploration + m_options.exploration_step);
        Decision decision{Action::GpuImproved, reason, 2};
        decision.draw = draw;
        return decision;
    }

    // The reason a switch left for the first frame of the new mode, else `otherwise`.
    std::uint8_t take_reason(std::uint8_t otherwise) {
        const std::uint8_t reason = m_next_reason.value_or(otherwise);
        m_next_reason.reset();
        return reason;
    }

    AdaptiveOptions m_options;
    Uniform m_uniform;
    Phase m_phase = Phase::Start;
    double m_aabb = k_unmeasured;
    double m_gpu = k_unmeasured;
    double m_rebuild_average = 0;
    double m_exploration;
    std::optional<std::uint8_t> m_next_reason;
};

}  // namespace

std::unique_ptr<Policy> make_thesis_policy(const AdaptiveOptions& options, Uniform uniform) {
    return std::make_unique<ThesisPolicy>(options, std::move(uniform));
}

}  // namespace collidescope::decision
