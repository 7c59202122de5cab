// Mode 2's frame: image-space cull of the inter-object PCS, final step over the survivors,
// then the mechanisms learn from what the frame measured.

#include "gpucull/gpu_culler.hpp"

#include "gpucull/final_hierarchy.hpp"
#include "stats/stopwatch.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace collidescope::gpucull {
namespace {

void check_config(const GpuCullConfig& config) {
    if (config.resolution < 1 || config.resolution > 8192) {
        throw std::invalid_argument("GPU cull resolution must be 1..8192, got " + std::to_string(config.resolution));
    }
    if (config.views.empty() || config.views.size() > 3 ||
        std::any_of(config.views.begin(), config.views.end(), [](int v) { return v < 0 || v > 2; })) {
        throw std::invalid_argument("GPU cull views must be one to three axes among 0, 1, 2");
    }
}

// Every object of an inter-object pair, ascending, with all its triangles.
std::vector<PcsObject> initial_pcs(const FrameContext& context) {
    std::vector<std::uint32_t> objects;
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b) continue;
        objects.push_back(pair.a);
        objects.push_back(pair.b);
    }
    std::sort(objects.begin(), objects.end());
    objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
    std::vector<PcsObject> pcs;
    for (const std::uint32_t object : objects) {
        PcsObject entry{object, {}};
        entry.triangles.resize(context.frame.objects[object].triangle_count());
        for (std::uint32_t i = 0; i < entry.triangles.size(); ++i) entry.triangles[i] = i;
        pcs.push_back(std::move(entry));
    }
    return pcs;
}

const GpuViewInfo& first_triangle_view(const GpuFrameInfo& info) {
    for (const GpuViewInfo& view : info.views) {
        if (view.level == 1) return view;
    }
    return info.views.front();
}

}  // namespace

GpuCuller::GpuCuller(const GpuCullConfig& config)
    : m_config((check_config(config), config)),
      m_views({config.view_decay_rate, true, config.seed}),
      m_per_query({config.naive ? 1 : config.triangles_per_query, config.max_triangles_per_query}),
      m_random(config.seed),
      m_context(make_cull_context(config.gl)) {}

GpuCuller::~GpuCuller() { make_current_for_cleanup(*m_context); }

std::vector<TrianglePair> GpuCuller::cull(const FrameContext& context, FrameStats& stats) {
    Stopwatch stopwatch;
    m_context->make_current();
    GpuFrameInfo info;
    info.renderer = m_context->renderer();
    CullPlan plan = frame_plan();
    plan.capture_depth = m_config.depth_every > 0 && context.frame.index % m_config.depth_every == 0;
    std::vector<PcsObject> pcs = initial_pcs(context);
    CullTimes times;
    cull_pcs(context.frame, pcs, plan, m_renderer, info, times);
    stats.ms.gpu_render += times.render;
    stats.ms.gpu_readback += times.readback;
    for (const PcsObject& object : pcs) {
        for (const std::uint32_t triangle : object.triangles) info.survivors.push_back({object.object, triangle});
    }
    stopwatch.lap_ms();

    FinalStepStats final_stats;
    std::vector<TrianglePair> candidates = final_step_candidates(context, pcs, final_stats);
    stats.ms.final_hierarchy += stopwatch.lap_ms();
    stats.ms.cull += times.render + times.readback + stats.ms.final_hierarchy;
    stats.counts.box_tests += final_stats.box_tests;
    stats.counts.nodes_visited += final_stats.nodes_visited;
    stats.counts.self_culled_triangles += final_stats.self_culled_triangles;
    stats.counts.adjacent_apart += final_stats.adjacent_apart;
    stats.counts.candidate_pairs += candidates.size();
    learn(plan, info, times, stats.ms.final_hierarchy);
    stats.gpu = std::move(info);
    return candidates;
}

// This frame's views and P: from the mechanisms, or the naive baseline's draws.
CullPlan GpuCuller::frame_plan() {
    CullPlan plan{m_config.resolution, m_config.views, m_per_query.current(), m_config.variant,
                  m_config.object_level, m_config.sort_objects && !m_config.naive};
    const int passes = static_cast<int>(m_config.views.size());
    if (m_config.naive) {
        std::vector<int> axes = {0, 1, 2};
        std::shuffle(axes.begin(), axes.end(), m_random);
        plan.views.assign(axes.begin(), axes.begin() + passes);
    } else if (m_config.view_matrix) {
        plan.views = m_views.choose(passes);
    }
    if (!m_config.adaptive_p && !m_config.naive) plan.triangles_per_query = m_config.triangles_per_query;
    return plan;
}

// Feeds the frame's results to Algorithm 2 and Algorithm 3, and records their state.
void GpuCuller::learn(const CullPlan& plan, GpuFrameInfo& info, const CullTimes& times, double final_ms) {
    for (const int view : plan.views) info.chosen_views.push_back(static_cast<std::uint8_t>(view));
    std::uint64_t triangle_queries = 0;
    double culled = 0;
    for (const GpuPassInfo& pass : info.passes) triangle_queries += pass.level == 1 ? pass.queries : 0;
    for (const GpuViewInfo& view : info.views) culled += view.level == 1 ? view.pcs_in - view.pcs_out : 0;
    if (info.queries > 0) info.query_ms = (times.render + times.readback) / static_cast<double>(info.queries);
    info.rebuild_ms_per_triangle = final_ms / std::max<double>(1, info.pcs_triangles_out);
    info.triangles_per_query = plan.variant == GpuCullVariant::Flags ? 0 : plan.triangles_per_query;
    if (m_config.naive) return;
    if (m_config.view_matrix) {
        m_views.update(plan.views, ViewConfiguration::culled_fractions(info, plan.views.size()));
        info.view_matrix = m_views.matrix();
    }
    if (m_config.adaptive_p && plan.variant == GpuCullVariant::Queries && triangle_queries > 0) {
        const double total = info.views.empty() ? 0 : static_cast<double>(first_triangle_view(info).pcs_in);
        m_per_query.update({culled, total, info.query_ms, info.rebuild_ms_per_triangle});
    }
}

}  // namespace collidescope::gpucull
