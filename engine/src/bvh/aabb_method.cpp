// The `aabb` method's frame: trees (swap, build, refit, policy), traversal, narrow phase.

#include "bvh/aabb_method.hpp"

#include "bvh/object_trees.hpp"
#include "pipeline/narrow_phase.hpp"

#include <algorithm>
#include <chrono>

namespace collidescope::bvh {
namespace {

double steady_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class AabbMethod final : public Method {
public:
    explicit AabbMethod(AabbConfig config) : m_config(std::move(config)), m_trees(m_config) {
        if (!m_config.clock_ms) m_config.clock_ms = &steady_ms;
    }

    std::string_view name() const override { return "aabb"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        const Frame& frame = context.frame;
        const std::vector<std::uint32_t> used = used_objects(context);
        AabbFrameInfo info;
        const double start = now();
        m_trees.begin_frame(frame.objects.size());
        m_trees.swap_finished(frame, m_config.background == BackgroundMode::NextFrame, info);
        m_trees.build_missing(frame, used, info);
        const double built = now();
        m_trees.refit_rest(frame, used);
        const double refitted = now();
        // The quality the policy judges: after refit, before any rebuild resets it.
        for (const std::uint32_t object : used) info.tree_quality = std::max(info.tree_quality, m_trees.at(object).quality);
        m_trees.apply_policy(frame, used, m_last_detection_ms, info);
        const double rebuilt = now();
        std::vector<TrianglePair> candidates;
        const TraversalStats traversal = traverse(roots(context), m_trees.views(frame, used), m_config.traversal, candidates);
        const double traversed = now();
        narrow_phase(frame, candidates, pairs, stats);
        const double narrowed = now();

        stats.ms.rebuild += (built - start) + (rebuilt - refitted);
        stats.ms.refit += refitted - built;
        stats.ms.traversal += traversed - rebuilt;
        stats.ms.cull += traversed - start;
        stats.counts.box_tests += traversal.box_tests;
        stats.counts.candidate_pairs += traversal.candidate_pairs;
        stats.counts.nodes_visited += traversal.nodes_visited;
        stats.counts.rebuilds += info.rebuilt_objects + info.background_started;
        stats.aabb = info;
        m_last_detection_ms = narrowed - rebuilt;
    }

private:
    double now() const { return m_config.clock_ms(); }

    // Objects that appear in some object pair this frame (self pairs only with self-collision).
    static std::vector<std::uint32_t> used_objects(const FrameContext& context) {
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

    std::vector<WorkItem> roots(const FrameContext& context) const {
        std::vector<WorkItem> items;
        for (const ObjectPair& pair : context.object_pairs) {
            if (pair.a == pair.b && !context.self_collision) continue;
            if (m_trees.at(pair.a).tree.empty() || m_trees.at(pair.b).tree.empty()) continue;
            items.push_back({pair.a, pair.b, 0, 0});
        }
        return items;
    }

    AabbConfig m_config;
    ObjectTrees m_trees;
    double m_last_detection_ms = 0;
};

}  // namespace

std::unique_ptr<Method> make_aabb_method(AabbConfig config) {
    return std::make_unique<AabbMethod>(std::move(config));
}

AabbConfig aabb_config(const AabbOptions& options) {
    AabbConfig config;
    config.build.builder = options.builder == AabbBuilder::Sah ? Builder::Sah : Builder::Lbvh;
    config.policy.rule = options.rebuild == AabbRebuildRule::Thesis  ? RebuildRule::Thesis
                         : options.rebuild == AabbRebuildRule::Never ? RebuildRule::Never
                                                                     : RebuildRule::Quality;
    config.policy.quality_limit = options.quality_limit;
    config.policy.thesis_fraction = options.thesis_fraction;
    config.background = options.background ? BackgroundMode::Async : BackgroundMode::Off;
    return config;
}

}  // namespace collidescope::bvh

namespace collidescope {

std::unique_ptr<Method> make_aabb_method() { return bvh::make_aabb_method(bvh::AabbConfig{}); }

std::unique_ptr<Method> make_aabb_method(const AabbOptions& options) {
    return bvh::make_aabb_method(bvh::aabb_config(options));
}

}  // namespace collidescope
