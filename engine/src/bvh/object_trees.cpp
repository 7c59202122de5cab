// The per-object tree stages of one frame: swap, build, refit, policy.

#include "bvh/object_trees.hpp"

#include "bvh/surface_patches.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace collidescope::bvh {
namespace {

bool same_topology(const ObjectTree& tree, const ObjectFrame& mesh) {
    return tree.topology && tree.topology->revision == mesh.topology->revision;
}

std::uint8_t bit(RebuildReason reason) { return static_cast<std::uint8_t>(reason); }

}  // namespace

ObjectTrees::ObjectTrees(const AabbConfig& config)
    : m_config(config), m_policy(config.policy) {}

void ObjectTrees::begin_frame(const Frame& frame, std::span<const std::uint32_t> self) {
    if (m_trees.size() < frame.objects.size()) m_trees.resize(frame.objects.size());
    for (ObjectTree& tree : m_trees) tree.fitted = tree.fresh = tree.self = false;
    for (const std::uint32_t object : self) {
        ObjectTree& slot = m_trees[object];
        const Topology& topology = *frame.objects[object].topology;
        if (slot.surface_revision != topology.revision) {
            slot.surface = surface_like(topology.triangles);
            slot.surface_revision = topology.revision;
        }
        slot.self = slot.surface;
    }
}

BuildConfig ObjectTrees::build_config(std::uint32_t object) const {
    BuildConfig config = m_config.build;
    config.surface_patches = m_trees[object].self;
    return config;
}

void ObjectTrees::notify(TreeEventKind kind, std::uint32_t object, const ObjectFrame& mesh) const {
    if (!m_config.on_tree) return;
    m_config.on_tree(TreeEvent{kind, object, m_trees[object].tree, mesh.topology->triangles, mesh.vertices});
}

void ObjectTrees::swap_finished(const Frame& frame, bool wait, AabbFrameInfo& info) {
    std::optional<std::vector<RebuiltTree>> finished = m_background.take(wait);
    if (!finished) return;
    for (RebuiltTree& rebuilt : *finished) {
        ObjectTree& slot = m_trees[rebuilt.job.object];
        slot.pending = false;
        // A topology change since the snapshot makes the new tree useless; the change itself
        // forces a build on the engine thread (build_missing).
        if (rebuilt.job.object >= frame.objects.size() ||
            rebuilt.job.topology->revision != frame.objects[rebuilt.job.object].topology->revision) {
            continue;
        }
        slot.tree = std::move(rebuilt.tree);
        slot.topology = rebuilt.job.topology;
        slot.build_ms = rebuilt.stats.ms;
        slot.quality = 1;
        ++info.background_swaps;
        if (m_config.on_tree) {
            m_config.on_tree(TreeEvent{TreeEventKind::Swap, rebuilt.job.object, slot.tree,
                                       rebuilt.job.topology->triangles, rebuilt.job.vertices});
        }
    }
}

void ObjectTrees::build(const Frame& frame, std::span<const std::uint32_t> objects) {
    // Objects in parallel, each build parallel inside (TBB nests them).
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const ObjectFrame& mesh = frame.objects[objects[k]];
            ObjectTree& slot = m_trees[objects[k]];
            const BuildStats stats =
                m_builder.build(mesh.topology->triangles, mesh.vertices, build_config(objects[k]), slot.tree);
            slot.topology = mesh.topology;
            slot.build_ms = stats.ms;
            slot.quality = 1;
            slot.fitted = slot.fresh = true;
        }
    });
    for (const std::uint32_t object : objects) notify(TreeEventKind::Build, object, frame.objects[object]);
}

void ObjectTrees::build_missing(const Frame& frame, std::span<const std::uint32_t> used, AabbFrameInfo& info) {
    std::vector<std::uint32_t> missing;
    for (const std::uint32_t object : used) {
        const ObjectTree& slot = m_trees[object];
        const RebuildReason reason = m_policy.decide({slot.topology != nullptr,
                                                      !same_topology(slot, frame.objects[object])});
        if (reason == RebuildReason::Initial || reason == RebuildReason::Topology) {
            info.rebuild_reasons |= bit(reason);
            missing.push_back(object);
        }
    }
    build(frame, missing);
    info.rebuilt_objects += static_cast<std::uint32_t>(missing.size());
}

void ObjectTrees::refit_rest(const Frame& frame, std::span<const std::uint32_t> used) {
    std::vector<std::uint32_t> stale;
    for (const std::uint32_t object : used) {
        if (!m_trees[object].fitted) stale.push_back(object);
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, stale.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const ObjectFrame& mesh = frame.objects[stale[k]];
            ObjectTree& slot = m_trees[stale[k]];
            // A tree built before its object was first tested against itself (or by a worker
            // started then) gets its patches now; one that no longer needs them drops them.
            if (slot.self && slot.tree.patches.empty()) build_surface_patches(slot.tree);
            if (!slot.self && !slot.tree.patches.empty()) slot.tree.patches = SurfacePatches{};
            slot.quality = refit(slot.tree, mesh.topology->triangles, mesh.vertices).quality;
            slot.fitted = true;
        }
    });
    for (const std::uint32_t object : stale) notify(TreeEventKind::Refit, object, frame.objects[object]);
}

void ObjectTrees::apply_policy(const Frame& frame, std::span<const std::uint32_t> used, double detection_ms, double traversal_ms,
                               AabbFrameInfo& info) {
    double rebuild_ms = 0;  // the thesis's "rebuild": every hierarchy in use
    for (const std::uint32_t object : used) rebuild_ms += m_trees[object].build_ms;
    const bool background = m_config.background != BackgroundMode::Off;
    std::vector<std::uint32_t> in_frame, to_worker;
    RebuildReason reason = RebuildReason::None;
    for (const std::uint32_t object : used) {
        const ObjectTree& slot = m_trees[object];
        if (slot.pending || slot.fresh || slot.tree.empty()) continue;
        const RebuildReason decided = m_policy.decide({true, false, slot.quality, detection_ms, rebuild_ms, traversal_ms});
        if (decided == RebuildReason::None) continue;
        reason = decided;
        const bool too_degraded = slot.quality > m_policy.config().in_frame_quality;
        (background && !too_degraded ? to_worker : in_frame).push_back(object);
    }
    if (in_frame.empty() && (to_worker.empty() || m_background.busy())) return;  // worker: one batch at a time
    if (!in_frame.empty()) {
        build(frame, in_frame);
        info.rebuilt_objects += static_cast<std::uint32_t>(in_frame.size());
    }
    if (!to_worker.empty() && !m_background.busy()) hand_to_worker(frame, to_worker, reason, info);
    info.rebuild_reasons |= bit(reason);
}

void ObjectTrees::fit_wide(std::span<const std::uint32_t> paired) {
    std::vector<std::uint8_t> now(m_trees.size(), 0);
    for (const std::uint32_t object : paired) now[object] = 1;
    std::vector<std::uint32_t> fit;
    for (std::uint32_t object = 0; object < m_trees.size(); ++object) {
        ObjectTree& slot = m_trees[object];
        slot.paired_frames = now[object] ? slot.paired_frames + 1 : 0;
        if (now[object] && !slot.tree.empty() && (slot.paired_frames >= 2 || wide_fitted(slot.tree))) {
            fit.push_back(object);
        }
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, fit.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) bvh::fit_wide(m_trees[fit[k]].tree);
    });
}

void ObjectTrees::hand_to_worker(const Frame& frame, std::span<const std::uint32_t> objects, RebuildReason reason,
                                 AabbFrameInfo& info) {
    std::vector<RebuildJob> jobs;
    for (const std::uint32_t object : objects) {
        const ObjectFrame& mesh = frame.objects[object];
        // The worker outlives this frame, whose vertices may view caller memory: it gets a copy.
        jobs.push_back({object, mesh.topology, mesh.vertices.to_vector(), frame.index, reason, build_config(object)});
        m_trees[object].pending = true;
    }
    m_background.start(std::move(jobs));
    info.background_started += static_cast<std::uint32_t>(objects.size());
}

bool ObjectTrees::start_rebuild(const Frame& frame, std::span<const std::uint32_t> objects, AabbFrameInfo& info) {
    if (m_background.busy()) return false;
    std::vector<std::uint32_t> chosen;
    for (const std::uint32_t object : objects) {
        if (object >= frame.objects.size() || object >= m_trees.size() || m_trees[object].tree.empty()) continue;
        if (!same_topology(m_trees[object], frame.objects[object])) continue;  // the engine thread builds those
        chosen.push_back(object);
    }
    if (chosen.empty()) return false;
    hand_to_worker(frame, chosen, RebuildReason::Thesis, info);
    info.rebuild_reasons |= bit(RebuildReason::Thesis);
    return true;
}

std::vector<MeshView> ObjectTrees::views(const Frame& frame, std::span<const std::uint32_t> used) const {
    std::vector<MeshView> views(frame.objects.size());
    for (const std::uint32_t object : used) {
        views[object] = {&m_trees[object].tree, frame.objects[object].topology->triangles,
                         frame.objects[object].vertices};
    }
    return views;
}

}  // namespace collidescope::bvh
