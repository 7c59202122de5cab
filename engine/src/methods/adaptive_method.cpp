// The adaptive method's frame: facts, decision, run, outcome, trace.

#include "stats/stopwatch.hpp"
#include "methods/adaptive_method.hpp"

#include "bvh/aabb_culler.hpp"
#include "decision/gpu_calibration.hpp"
#include "methods/aabb_method.hpp"
#include "methods/gpu_method.hpp"
#include "methods/hybrid_method.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <chrono>
#include <random>

namespace collidescope {
namespace {

using namespace decision;

// Triangles of the objects in inter-object pairs.
std::uint64_t pcs_triangles(const FrameContext& context) {
    std::vector<bool> in(context.frame.objects.size(), false);
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a != pair.b) in[pair.a] = in[pair.b] = true;
    }
    std::uint64_t triangles = 0;
    for (std::size_t o = 0; o < in.size(); ++o) triangles += in[o] ? context.frame.objects[o].triangle_count() : 0;
    return triangles;
}

// The AABB trees' configuration, on the adaptive method's clock (so that a scripted clock
// scripts the rebuild times the policy sees too).
bvh::AabbConfig culler_config(const PipelineConfig& pipeline, const std::function<double()>& clock,
                               bool join_next_frame) {
    bvh::AabbConfig config = bvh::aabb_config(pipeline.aabb, pipeline.threads);
    config.clock_ms = clock;
    if (join_next_frame) config.background = bvh::BackgroundMode::NextFrame;
    return config;
}

class AdaptiveMethod final : public Method {
public:
    AdaptiveMethod(const PipelineConfig& config, AdaptiveParts parts)
        : m_clock(parts.clock_ms ? std::move(parts.clock_ms) : std::function<double()>(&steady_ms)),
          m_culler(std::make_shared<bvh::AabbCuller>(culler_config(config, m_clock, parts.join_rebuilds_next_frame))),
          m_aabb(make_aabb_method(m_culler)) {
        if (!parts.without_gpu) make_gpu_methods(config);
        if (!parts.uniform) {
            parts.uniform = [random = std::mt19937_64(config.adaptive.seed)]() mutable {
                return std::uniform_real_distribution<double>(0.0, 1.0)(random);
            };
        }
        if (parts.policy) {
            m_policy = parts.policy();
        } else if (config.adaptive.policy == AdaptivePolicy::Thesis) {
            m_policy = make_thesis_policy(config.adaptive, std::move(parts.uniform));
        } else {
            m_policy = make_cost_policy(config.adaptive, parts.prior);
            m_gpu_config = config.gpu;
        }
    }

    std::string_view name() const override { return "adaptive"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        FrameFacts facts;
        facts.gpu_available = m_gpu_improved != nullptr;
        facts.rebuild_finished = m_culler->rebuild_finished();
        facts.rebuild_running = m_culler->rebuild_in_flight() && !facts.rebuild_finished;
        facts.rebuild_average_ms = m_rebuild_count > 0 ? m_rebuild_sum / m_rebuild_count : 0.0;
        facts.pcs_triangles = pcs_triangles(context);
        facts.marked_triangles = std::min(facts.pcs_triangles, 2 * m_last_inter_candidates);
        const Decision decision = m_policy->decide(facts);
        DecisionInfo info = m_policy->inputs();  // as the policy judged them

        const double start = m_clock();
        if (decision.start_rebuild) {
            AabbFrameInfo aabb_info;
            m_culler->start_rebuild(context.frame, aabb_info);
            stats.aabb = aabb_info;
        }
        if (decision.calibrate) calibrate();  // inside the frame: its time is the frame's
        Outcome outcome;
        switch (decision.action) {
        case Action::Aabb: outcome.aabb_ms = timed(*m_aabb, context, pairs, stats); break;
        case Action::GpuPlain: outcome.gpu_ms = timed(*m_gpu_plain, context, pairs, stats); break;
        case Action::GpuImproved: outcome.gpu_ms = timed(*m_gpu_improved, context, pairs, stats); break;
        case Action::Hybrid: outcome.hybrid_ms = timed(*m_hybrid, context, pairs, stats); break;
        case Action::SampleBoth: {
            outcome.aabb_ms = timed(*m_aabb, context, pairs, stats);
            FrameStats sample_stats;  // the GPU sample's pairs and details are dropped
            std::vector<TrianglePair> sample_pairs;
            outcome.gpu_ms = timed(*m_gpu_plain, context, sample_pairs, sample_stats);
            stats.ms.gpu_render += sample_stats.ms.gpu_render;
            stats.ms.gpu_readback += sample_stats.ms.gpu_readback;
            stats.ms.cull += sample_stats.ms.cull;
            stats.gpu = std::move(sample_stats.gpu);
            break;
        }
        }
        outcome.frame_ms = m_clock() - start;
        if (!std::isnan(outcome.aabb_ms)) m_last_inter_candidates = stats.counts.candidate_pairs;
        if (stats.aabb && stats.aabb->rebuilt_objects > 0) {  // AABB Rebuild Average: engine-thread builds
            m_rebuild_sum += stats.ms.rebuild;
            ++m_rebuild_count;
        }
        m_policy->observe(outcome);

        info.mode = decision.mode;
        info.action = static_cast<std::uint8_t>(decision.action);
        info.reason = decision.reason;
        info.switched = m_last_mode != 0 && m_last_mode != decision.mode;
        info.rebuilding = facts.rebuild_running || decision.start_rebuild;
        info.draw = decision.draw;
        m_last_mode = decision.mode;
        stats.decision = info;
    }

private:
    void make_gpu_methods(const PipelineConfig& config) {
        try {
            GpuCullConfig plain = config.gpu;  // GPU 1: "without metrics": fixed views and P
            plain.view_matrix = false;
            plain.adaptive_p = false;
            m_gpu_plain = make_gpu_method(plain);
            m_gpu_improved = make_gpu_method(config.gpu);
            m_hybrid = make_hybrid_method(m_culler, config.gpu);
        } catch (const UnavailableError&) {
            m_gpu_plain.reset();
            m_gpu_improved.reset();
            m_hybrid.reset();
        }
    }

    // Measures the GPU prior for the policy (without it, the GPU stays out).
    void calibrate() {
        try {
            m_policy->set_gpu_prior(measure_gpu_prior(m_gpu_config));
        } catch (const std::exception&) {  // no GL after all: the GPU stays out
        }
    }

    double timed(Method& method, const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) {
        const double start = m_clock();
        method.detect(context, pairs, stats);
        return m_clock() - start;
    }

    std::function<double()> m_clock;
    std::shared_ptr<bvh::AabbCuller> m_culler;
    std::unique_ptr<Method> m_aabb;
    std::unique_ptr<Method> m_gpu_plain;
    std::unique_ptr<Method> m_gpu_improved;
    std::unique_ptr<Method> m_hybrid;
    std::unique_ptr<Policy> m_policy;
    GpuCullConfig m_gpu_config;  // for the GPU prior's measurement
    std::uint8_t m_last_mode = 0;
    std::uint64_t m_last_inter_candidates = 0;  // candidate pairs of the last AABB run
    double m_rebuild_sum = 0;   // ms.rebuild of the frames that built hierarchies on the engine thread
    std::uint32_t m_rebuild_count = 0;
};

}  // namespace

std::unique_ptr<Method> make_adaptive_method(const PipelineConfig& config, AdaptiveParts parts) {
    return std::make_unique<AdaptiveMethod>(config, std::move(parts));
}

}  // namespace collidescope
