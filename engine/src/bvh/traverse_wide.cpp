// Tree-vs-tree traversal step on the wide layouts (wide_tree.hpp) for the per-frame
// traversal: wide_step.hpp's step, two leaves' triangle pairs into the candidates.

#include "bvh/traverse.hpp"
#include "bvh/wide_step.hpp"

namespace collidescope::bvh {
namespace {

// Two leaves of different objects: every triangle pair on the double boxes (the leaf entries
// carry the slot ranges, so no binary node is read), the candidates exactly the pairs whose
// closed boxes overlap.
void wide_leaf_pair(const WorkItem& item, const Tree& a, std::uint32_t first_a, std::uint32_t count_a, const Tree& b,
                    std::uint32_t first_b, std::uint32_t count_b, CandidateBuffer& candidates, TraversalStats& stats) {
    for (std::uint32_t i = first_a; i < first_a + count_a; ++i) {
        const Aabb& box = a.leaf_boxes[i];
        for (std::uint32_t j = first_b; j < first_b + count_b; ++j) {
            if (overlaps(box, b.leaf_boxes[j])) {
                candidates.push_back({item.obj_a, a.triangle_ids[i], item.obj_b, b.triangle_ids[j]});
            }
        }
    }
    stats.box_tests += std::uint64_t{count_a} * count_b;
}

}  // namespace

void step_wide(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats) {
    const Tree& tree_a = *meshes[item.obj_a].tree;
    const Tree& tree_b = *meshes[item.obj_b].tree;
    ++stats.nodes_visited;
    stats.box_tests += wide::step(
        tree_a, item.node_a, tree_b, item.node_b,
        [&](std::uint32_t entry_a, std::uint32_t entry_b) {
            stack.push_back({item.obj_a, item.obj_b, entry_a, entry_b, true});
        },
        [&](std::uint32_t first_a, std::uint32_t count_a, std::uint32_t first_b, std::uint32_t count_b) {
            const std::size_t before = candidates.size();
            wide_leaf_pair(item, tree_a, first_a, count_a, tree_b, first_b, count_b, candidates, stats);
            stats.candidate_pairs += candidates.size() - before;
        });
}

void add_pair_root(std::uint32_t a, std::uint32_t b, std::span<const MeshView> meshes, std::vector<WorkItem>& roots) {
    const MeshView& x = meshes[a];
    const MeshView& y = meshes[b];
    const bool masked = !x.alive_nodes.empty() || !y.alive_nodes.empty() || !x.alive_triangles.empty() ||
                        !y.alive_triangles.empty();
    if (a == b || masked || !wide_fitted(*x.tree) || !wide_fitted(*y.tree)) {
        roots.push_back({a, b, 0, 0});
    } else if (overlaps(x.tree->nodes[0].box, y.tree->nodes[0].box)) {
        roots.push_back({a, b, wide_root(*x.tree), wide_root(*y.tree), true});
    }
}

}  // namespace collidescope::bvh
