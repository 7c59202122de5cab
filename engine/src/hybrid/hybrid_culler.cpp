// The hybrid framework's frame: AABB marks, GPU cull of the marked set, final traversal on the
// culled trees; and the analysis of thesis 4.3.

#include "hybrid/hybrid_culler.hpp"

#include "gpucull/image_space_cull.hpp"

#include <algorithm>
#include <limits>

namespace collidescope::hybrid {
namespace {

using gpucull::PcsObject;

// Step A's marks: per object (ascending), the triangles of the inter-object candidates.
std::vector<PcsObject> marked_triangles(std::span<const TrianglePair> inter, std::size_t objects) {
    std::vector<std::vector<std::uint32_t>> marks(objects);
    for (const TrianglePair& pair : inter) {
        marks[pair.obj_a].push_back(pair.tri_a);
        marks[pair.obj_b].push_back(pair.tri_b);
    }
    std::vector<PcsObject> pcs;
    for (std::uint32_t object = 0; object < objects; ++object) {
        std::vector<std::uint32_t>& list = marks[object];
        if (list.empty()) continue;
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        pcs.push_back({object, std::move(list)});
    }
    return pcs;
}

}  // namespace

HybridCuller::HybridCuller(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu)
    : m_culler(std::move(culler)),
      m_config(gpu),
      m_views({gpu.view_decay_rate, true, gpu.seed}),
      m_context(gpucull::make_cull_context(gpu.gl)) {}

HybridCuller::~HybridCuller() { gpucull::make_current_for_cleanup(*m_context); }

bvh::TraversalStats HybridCuller::cull(const FrameContext& context, std::vector<TrianglePair>& candidates,
                                       HybridFrameInfo& info, FrameStats& stats) {
    // A: the AABB traversal down to the leaves; its candidates are marks, not tests.
    std::vector<TrianglePair> first;
    const bvh::TraversalStats traversal = m_culler->cull(context, first, stats);
    candidates.clear();
    std::vector<TrianglePair> inter;
    for (const TrianglePair& pair : first) (pair.obj_a == pair.obj_b ? candidates : inter).push_back(pair);
    info.a1 = traversal.nodes_visited;
    info.tri_1 = inter.size();
    if (!inter.empty()) cull_and_retraverse(context, inter, candidates, info, stats);
    stats.counts.candidate_pairs = candidates.size();
    return traversal;
}

// B, C, D: the GPU culls the marked triangles; the survivors' marks percolate up the trees;
// the final traversal on the culled trees appends its candidates.
void HybridCuller::cull_and_retraverse(const FrameContext& context, std::span<const TrianglePair> inter,
                                       std::vector<TrianglePair>& candidates, HybridFrameInfo& info,
                                       FrameStats& stats) {
    const Frame& frame = context.frame;
    std::vector<PcsObject> pcs = marked_triangles(inter, frame.objects.size());
    for (const PcsObject& object : pcs) info.tri_r += object.triangles.size();
    m_context->make_current();
    GpuFrameInfo gpu;
    gpu.renderer = m_context->renderer();
    gpucull::CullPlan plan{m_config.resolution, m_config.views, m_config.triangles_per_query, m_config.variant,
                           m_config.object_level, m_config.sort_objects};
    if (m_config.view_matrix) plan.views = m_views.choose(static_cast<int>(m_config.views.size()));
    gpucull::CullTimes times;
    gpucull::cull_pcs(frame, pcs, plan, m_renderer, gpu, times);
    stats.ms.gpu_render += times.render;
    stats.ms.gpu_readback += times.readback;
    m_gpu_ms = times.render + times.readback;

    std::vector<std::vector<std::uint8_t>> alive(frame.objects.size());
    for (const PcsObject& object : pcs) {
        alive[object.object].assign(frame.objects[object.object].triangle_count(), 0);
        for (const std::uint32_t triangle : object.triangles) {
            alive[object.object][triangle] = 1;
            gpu.survivors.push_back({object.object, triangle});
        }
    }
    const std::size_t before = candidates.size();
    const bvh::TraversalStats final_traversal = m_culler->traverse_culled(context, alive, candidates);
    info.a2 = final_traversal.nodes_visited;
    info.tri_2 = candidates.size() - before;
    stats.ms.final_hierarchy += final_traversal.ms;
    stats.ms.cull += m_gpu_ms + final_traversal.ms;
    stats.counts.box_tests += final_traversal.box_tests;
    stats.counts.nodes_visited += final_traversal.nodes_visited;

    for (const int view : plan.views) gpu.chosen_views.push_back(static_cast<std::uint8_t>(view));
    if (gpu.queries > 0) gpu.query_ms = m_gpu_ms / static_cast<double>(gpu.queries);
    gpu.triangles_per_query = plan.variant == GpuCullVariant::Flags ? 0 : plan.triangles_per_query;
    if (m_config.view_matrix) {
        m_views.update(plan.views, gpucull::ViewConfiguration::culled_fractions(gpu, plan.views.size()));
        gpu.view_matrix = m_views.matrix();
    }
    stats.gpu = std::move(gpu);
}

// Equations 4.11-4.17 (see the header for the unit costs).
void HybridCuller::analyse(HybridFrameInfo& info, double traversal_ms, const FrameStats& stats) {
    if (info.a1 > 0) info.a_i_ms = traversal_ms / static_cast<double>(info.a1);
    if (stats.counts.exact_tests > 0) m_t_i = stats.ms.narrow / static_cast<double>(stats.counts.exact_tests);
    info.t_i_ms = m_t_i;
    if (info.tri_r > 0) m_o = m_gpu_ms / static_cast<double>(info.tri_r);
    info.o_ms = m_o;
    info.unculled = info.tri_1 == 0 ? 1.0 : static_cast<double>(info.tri_2) / static_cast<double>(info.tri_1);
    const double a1 = static_cast<double>(info.a1), a2 = static_cast<double>(info.a2);
    const double tri_1 = static_cast<double>(info.tri_1), tri_r = static_cast<double>(info.tri_r);
    info.pure_aabb_ms = a1 * info.a_i_ms + tri_1 * info.t_i_ms;
    info.hybrid_ms = a1 * info.a_i_ms + tri_r * info.o_ms + a2 * info.a_i_ms + static_cast<double>(info.tri_2) * info.t_i_ms;
    const double kept = 1.0 - info.unculled;
    info.tri_1_needed = kept > 0 && info.t_i_ms > 0 ? info.o_ms / (info.t_i_ms * kept)
                                                    : std::numeric_limits<double>::infinity();
    info.predicted_hybrid_wins = tri_1 * info.t_i_ms > tri_r * info.o_ms + info.unculled * tri_1 * info.t_i_ms;
}

}  // namespace collidescope::hybrid
