// Hierarchies over the GPU cull's survivors, and their traversal.

#include "gpucull/final_hierarchy.hpp"

#include "bvh/bvh.hpp"
#include "bvh/surface_patches.hpp"
#include "bvh/traverse.hpp"

#include <algorithm>

namespace collidescope::gpucull {
namespace {

// One object's hierarchy over a subset of its triangles; `ids` maps back to file order.
struct Subset {
    std::vector<TriIndices> triangles;
    std::vector<std::uint32_t> ids;
    bvh::Tree tree;
};

void fill_subset(const ObjectFrame& object, const std::vector<std::uint32_t>* survivors, Subset& subset) {
    if (survivors != nullptr) {
        subset.ids = *survivors;
    } else {
        subset.ids.resize(object.triangle_count());
        for (std::uint32_t i = 0; i < subset.ids.size(); ++i) subset.ids[i] = i;
    }
    for (const std::uint32_t id : subset.ids) subset.triangles.push_back(object.topology->triangles[id]);
    bvh::BuildConfig config;
    // A whole object tested against itself: its surface patches let the self-traversal skip
    // what is proven embedded (a soup has none worth building).
    config.surface_patches = survivors == nullptr && bvh::surface_like(subset.triangles);
    if (!subset.triangles.empty()) bvh::build_tree(subset.triangles, object.vertices, config, subset.tree);
}

}  // namespace

std::vector<TrianglePair> final_step_candidates(const FrameContext& context, const std::vector<PcsObject>& pcs,
                                                FinalStepStats& stats) {
    const Frame& frame = context.frame;
    const auto survivors = [&](std::uint32_t object) -> const std::vector<std::uint32_t>* {
        const auto it = std::lower_bound(pcs.begin(), pcs.end(), object,
                                         [](const PcsObject& e, std::uint32_t o) { return e.object < o; });
        return it != pcs.end() && it->object == object ? &it->triangles : nullptr;
    };
    // Objects that need a hierarchy: survivors of the cull, or every triangle under self-collision.
    // An object both in the PCS and self-colliding keeps all its triangles (a superset: exact).
    std::vector<Subset> subsets(frame.objects.size());
    std::vector<bvh::MeshView> views(frame.objects.size());
    std::vector<bvh::WorkItem> roots;
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b && context.self_collision) roots.push_back({pair.a, pair.a, 0, 0});
        if (pair.a != pair.b && survivors(pair.a) != nullptr && survivors(pair.b) != nullptr) {
            roots.push_back({pair.a, pair.b, 0, 0});
        }
    }
    std::vector<std::uint8_t> whole(frame.objects.size(), 0);
    for (const bvh::WorkItem& root : roots) {
        if (root.obj_a == root.obj_b) whole[root.obj_a] = 1;
    }
    for (const bvh::WorkItem& root : roots) {
        for (const std::uint32_t object : {root.obj_a, root.obj_b}) {
            Subset& subset = subsets[object];
            if (!subset.ids.empty()) continue;
            fill_subset(frame.objects[object], whole[object] ? nullptr : survivors(object), subset);
            views[object] = {&subset.tree, subset.triangles, frame.objects[object].vertices};
        }
    }
    std::erase_if(roots, [&](const bvh::WorkItem& r) { return subsets[r.obj_a].tree.empty() || subsets[r.obj_b].tree.empty(); });

    std::vector<TrianglePair> candidates;
    const bvh::TraversalStats traversal = bvh::traverse(roots, views, bvh::TraversalConfig{}, candidates);
    // Back to the file's triangle ids: ids ascend within a subset, so canonical order holds.
    for (TrianglePair& pair : candidates) {
        pair.tri_a = subsets[pair.obj_a].ids[pair.tri_a];
        pair.tri_b = subsets[pair.obj_b].ids[pair.tri_b];
    }
    stats.nodes_visited = traversal.nodes_visited;
    stats.box_tests = traversal.box_tests;
    stats.self_culled_triangles = traversal.self_culled_triangles;
    stats.adjacent_apart = traversal.adjacent_apart;
    return candidates;
}

}  // namespace collidescope::gpucull
