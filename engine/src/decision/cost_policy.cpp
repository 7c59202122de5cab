// Our policy (docs/explanation/decision.md): keep an estimate of each method's detection time, run the
// cheapest, and re-measure the others within a budget.
//
// - Estimates: AABB and hybrid, exponential moving averages of their measured times; the GPU,
//   a per-triangle model (prior measured inside a frame once affordable, then scaled by the moving
//   average of measured / predicted), so it follows the PCS size between measurements.
// - Probing: a method not chosen is run once probe_budget x (ms elapsed since it last ran)
//   reaches its predicted extra cost over the cheapest; so each method's probes cost at most
//   probe_budget of the run's time when the predictions hold, however long the run.
// - The AABB trees go stale while other methods serve frames: when the cheapest is not AABB,
//   a rebuild starts in a thread (the thesis's contribution 3), and AABB is probed as soon as
//   it finished.

#include "decision/policy.hpp"

#include <algorithm>
#include <array>

namespace collidescope::decision {
namespace {

constexpr std::size_t k_aabb = 0, k_gpu = 1, k_hybrid = 2;
constexpr std::array<Action, 3> k_actions = {Action::Aabb, Action::GpuImproved, Action::Hybrid};

class CostPolicy final : public Policy {
public:
    CostPolicy(const AdaptiveOptions& options, std::optional<GpuCostPrior> prior)
        : m_options(options), m_prior(prior.value_or(GpuCostPrior{})), m_has_prior(prior.has_value()) {}

    Decision decide(const FrameFacts& facts) override {
        m_facts = facts;
        if (m_rebuild_pending && !facts.rebuild_running && !facts.rebuild_finished && !m_rebuild_asked) {
            m_rebuild_pending = false;  // the method had nothing to rebuild
        }
        m_rebuild_asked = false;
        m_predicted = {m_estimate[k_aabb], gpu_prediction(facts.pcs_triangles), hybrid_prediction(facts.marked_triangles)};
        if (std::isnan(m_estimate[k_aabb]) || !facts.gpu_available) return chosen(k_aabb, k_reason_cost_probe);
        if (!m_has_prior) {  // the GPU is unknown: measure its prior once the budget affords it
            Decision decision = chosen(k_aabb, k_reason_cost_cheapest);
            decision.calibrate = !m_calibration_asked && m_options.probe_budget * m_elapsed >= m_options.calibration_ms;
            m_calibration_asked = m_calibration_asked || decision.calibrate;
            return decision;
        }
        if (facts.rebuild_finished && m_rebuild_pending) {  // measure the rebuilt trees now
            m_rebuild_pending = false;
            return chosen(k_aabb, k_reason_cost_probe);
        }
        const std::size_t best = cheapest();
        // The stalest affordable alternative, if any.
        std::size_t probe = best;
        double slack = 0;
        for (std::size_t m = 0; m < 3; ++m) {
            if (m == best || !enabled(m)) continue;
            const double extra = std::max(0.0, m_predicted[m] - m_predicted[best]);
            const double allowance = m_options.probe_budget * m_since[m] - extra;
            if (allowance >= 0 && (probe == best || allowance > slack)) {
                probe = m;
                slack = allowance;
            }
        }
        Decision decision = probe != best ? chosen(probe, k_reason_cost_probe) : chosen(best, k_reason_cost_cheapest);
        if (best != k_aabb && !facts.rebuild_running && !facts.rebuild_finished && !m_rebuild_pending) {
            decision.start_rebuild = true;
            m_rebuild_pending = m_rebuild_asked = true;
        }
        return decision;
    }

    void observe(const Outcome& outcome) override {
        for (double& since : m_since) since += outcome.frame_ms;
        m_elapsed += outcome.frame_ms;
        const double alpha = m_options.smoothing;
        const auto blend = [alpha](double& estimate, double measured) {
            estimate = std::isnan(estimate) ? measured : (1 - alpha) * estimate + alpha * measured;
        };
        if (!std::isnan(outcome.aabb_ms)) {
            blend(m_estimate[k_aabb], outcome.aabb_ms);
            m_since[k_aabb] = 0;
        }
        if (!std::isnan(outcome.gpu_ms)) {
            const double model = gpu_model(m_facts.pcs_triangles);
            if (model > 0) blend(m_gpu_scale, outcome.gpu_ms / model);
            m_since[k_gpu] = 0;
        }
        if (!std::isnan(outcome.hybrid_ms)) {
            blend(m_estimate[k_hybrid], outcome.hybrid_ms);
            m_since[k_hybrid] = 0;
        }
    }

    void set_gpu_prior(const GpuCostPrior& prior) override {
        m_prior = prior;
        m_has_prior = true;
    }

    DecisionInfo inputs() const override {
        DecisionInfo info;
        info.policy = 1;
        info.aabb_ms = m_predicted[k_aabb];
        info.gpu_ms = m_has_prior ? m_predicted[k_gpu] : k_unmeasured;  // no prior yet: no estimate
        info.hybrid_ms = m_has_prior ? m_predicted[k_hybrid] : k_unmeasured;
        info.rebuild_avg_ms = m_facts.rebuild_average_ms;
        info.exploration = m_options.probe_budget;
        return info;
    }

private:
    bool enabled(std::size_t m) const { return m != k_hybrid || m_options.use_hybrid; }

    double gpu_model(std::uint64_t triangles) const {
        return m_prior.fixed_ms + m_prior.per_triangle_ms * static_cast<double>(triangles);
    }
    double gpu_prediction(std::uint64_t triangles) const {
        return (std::isnan(m_gpu_scale) ? 1.0 : m_gpu_scale) * gpu_model(triangles);
    }
    // Before its first run: the AABB's time plus the GPU's on the marked triangles.
    double hybrid_prediction(std::uint64_t marked) const {
        if (!std::isnan(m_estimate[k_hybrid])) return m_estimate[k_hybrid];
        return m_estimate[k_aabb] + gpu_prediction(marked);
    }

    std::size_t cheapest() const {
        std::size_t best = k_aabb;
        for (std::size_t m = 1; m < 3; ++m) {
            if (enabled(m) && m_predicted[m] < m_predicted[best]) best = m;
        }
        return best;
    }

    Decision chosen(std::size_t m, std::uint8_t reason) const {
        return {k_actions[m], reason, static_cast<std::uint8_t>(m == k_gpu ? 2 : 1)};
    }

    AdaptiveOptions m_options;
    GpuCostPrior m_prior;
    bool m_has_prior = false;
    bool m_calibration_asked = false;  // asked once; a failed measurement is not retried
    double m_elapsed = 0;              // ms of every frame so far
    FrameFacts m_facts;
    std::array<double, 3> m_estimate = {k_unmeasured, k_unmeasured, k_unmeasured};  // gpu: unused
    std::array<double, 3> m_predicted = {k_unmeasured, k_unmeasured, k_unmeasured};
    std::array<double, 3> m_since = {0, 0, 0};  // ms of frames since each method last ran
    double m_gpu_scale = k_unmeasured;
    bool m_rebuild_pending = false;  // a rebuild we started has not been measured yet
    bool m_rebuild_asked = false;    // asked for one on the previous decide
};

}  // namespace

std::unique_ptr<Policy> make_cost_policy(const AdaptiveOptions& options, std::optional<GpuCostPrior> prior) {
    return std::make_unique<CostPolicy>(options, prior);
}

}  // namespace collidescope::decision
