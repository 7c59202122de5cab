// Mode 1's frame: trees (swap, build, refit, policy), then the traversal.

#include "stats/stopwatch.hpp"
#include "bvh/aabb_culler.hpp"

#include "bvh/object_trees.hpp"

#include <tbb/info.h>

#include <algorithm>
#include <chrono>

namespace collidescope::bvh {
namespace {

// Objects that appear in some object pair this frame (self pairs only with self-collision).
std::vector<std::uint32_t> used_objects(const FrameContext& context) {
    std::vector<bool> used(context.frame.objects.size(), false);
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b && !context.self_collision) continue;
        used[pair.a] = used[pair.b] = true;
    }
    std::vector<std::uint32_t> objects;
    for (std::uint32_t o = 0; o < used.size(); ++o) {
        if (used[o]) objects.push_back(o);
    }
    return objects;
}

// Objects tested against themselves this frame: their trees carry surface patches.
std::vector<std::uint32_t> self_objects(const FrameContext& context) {
    std::vector<std::uint32_t> objects;
    if (!context.self_collision) return objects;
    for (const ObjectPair& pair : context.object_pairs)
        if (pair.a == pair.b) objects.push_back(pair.a);
    return objects;
}

// Objects in some pair with another object this frame (ObjectTrees::fit_wide decides which
// of them get a wide layout).
std::vector<std::uint32_t> paired_objects(const FrameContext& context) {
    std::vector<bool> paired(context.frame.objects.size(), false);
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a != pair.b) paired[pair.a] = paired[pair.b] = true;
    }
    std::vector<std::uint32_t> objects;
    for (std::uint32_t o = 0; o < paired.size(); ++o) {
        if (paired[o]) objects.push_back(o);
    }
    return objects;
}

std::vector<WorkItem> roots(const FrameContext& context, const ObjectTrees& trees, std::span<const MeshView> views) {
    std::vector<WorkItem> items;
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b && !context.self_collision) continue;
        if (trees.at(pair.a).tree.empty() || trees.at(pair.b).tree.empty()) continue;
        add_pair_root(pair.a, pair.b, views, items);
    }
    return items;
}

}  // namespace

AabbCuller::AabbCuller(AabbConfig config) : m_config(std::move(config)) {
    if (!m_config.clock_ms) m_config.clock_ms = &steady_ms;
    m_trees = std::make_unique<ObjectTrees>(m_config);
}

AabbCuller::~AabbCuller() = default;

TraversalStats AabbCuller::cull(const FrameContext& context, std::vector<TrianglePair>& candidates,
                                FrameStats& stats) {
    const Frame& frame = context.frame;
    m_used = used_objects(context);
    AabbFrameInfo info = stats.aabb.value_or(AabbFrameInfo{});
    const double start = now();
    m_trees->begin_frame(frame, self_objects(context));
    m_trees->swap_finished(frame, m_config.background == BackgroundMode::NextFrame, info);
    m_trees->build_missing(frame, m_used, info);
    const double built = now();
    m_trees->refit_rest(frame, m_used);
    const double refitted = now();
    // The quality the policy judges: after refit, before any rebuild resets it.
    for (const std::uint32_t object : m_used) info.tree_quality = std::max(info.tree_quality, m_trees->at(object).quality);
    m_trees->apply_policy(frame, m_used, m_last_detection_ms, m_last_traversal_ms, info);
    const double rebuilt = now();
    m_trees->fit_wide(paired_objects(context));
    const double widened = now();
    const std::vector<MeshView> views = m_trees->views(frame, m_used);
    const TraversalStats traversal =
        traverse(roots(context, *m_trees, views), views, m_config.traversal, candidates, m_buffers.get());
    const double traversed = now();

    stats.ms.rebuild += (built - start) + (rebuilt - refitted);
    stats.ms.refit += (refitted - built) + (widened - rebuilt);
    stats.ms.traversal += traversed - widened;
    stats.ms.cull += traversed - start;
    stats.counts.box_tests += traversal.box_tests;
    stats.counts.candidate_pairs += traversal.candidate_pairs;
    stats.counts.nodes_visited += traversal.nodes_visited;
    stats.counts.self_culled_triangles += traversal.self_culled_triangles;
    stats.counts.adjacent_apart += traversal.adjacent_apart;
    stats.counts.rebuilds += info.rebuilt_objects + info.background_started;
    stats.aabb = info;
    TraversalStats result = traversal;
    result.ms = traversed - widened;
    return result;
}

TraversalStats AabbCuller::traverse_culled(const FrameContext& context,
                                           const std::vector<std::vector<std::uint8_t>>& alive,
                                           std::vector<TrianglePair>& candidates) {
    std::vector<MeshView> views = m_trees->views(context.frame, m_used);
    std::vector<std::vector<std::uint8_t>> alive_nodes(views.size());
    for (const std::uint32_t object : m_used) {
        if (object >= alive.size() || alive[object].empty() || m_trees->at(object).tree.empty()) continue;
        alive_nodes[object] = percolate_alive(m_trees->at(object).tree, alive[object]);
        views[object].alive_nodes = alive_nodes[object];
        views[object].alive_triangles = alive[object];
    }
    std::vector<WorkItem> items;
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b) continue;
        if (alive_nodes[pair.a].empty() || alive_nodes[pair.b].empty()) continue;
        if (!alive_nodes[pair.a][0] || !alive_nodes[pair.b][0]) continue;
        items.push_back({pair.a, pair.b, 0, 0});
    }
    const double start = now();
    TraversalStats stats = traverse(std::move(items), views, m_config.traversal, candidates, m_buffers.get());
    stats.ms = now() - start;
    return stats;
}

bool AabbCuller::start_rebuild(const Frame& frame, AabbFrameInfo& info) {
    return m_trees->start_rebuild(frame, m_used, info);
}

bool AabbCuller::rebuild_in_flight() const { return m_trees->rebuild_in_flight(); }

bool AabbCuller::rebuild_finished() const {
    if (m_config.background == BackgroundMode::NextFrame) return m_trees->rebuild_in_flight();
    return m_trees->rebuild_finished();
}

bool rebuild_in_background(AabbBackground mode, int threads) {
    if (mode != AabbBackground::Auto) return mode == AabbBackground::On;
    return threads > 0 && threads < tbb::info::default_concurrency();
}

AabbConfig aabb_config(const AabbOptions& options, int threads) {
    AabbConfig config;
    config.build.builder = options.builder;
    config.policy.rule = options.rebuild;
    config.policy.quality_limit = options.quality_limit;
    config.policy.payback_frames = options.payback_frames;
    config.policy.thesis_fraction = options.thesis_fraction;
    config.background = rebuild_in_background(options.background, threads) ? BackgroundMode::Async : BackgroundMode::Off;
    return config;
}

}  // namespace collidescope::bvh
