// Tree-vs-tree traversal step: simultaneous descent, splitting the node with the larger
// surface (a leaf is never split); leaves meet triangle by triangle on closed boxes (the
// refit's Tree::leaf_boxes), and two subtrees of one object drop the adjacent pairs that
// adjacent_apart proves apart. A split tests each child pair's boxes before pushing it, so
// pairs that do not overlap never reach the stack (a popped pair is tested again, its boxes in cache: roots arrive untested).

#include "bvh/traverse.hpp"
#include "geometry/adjacent_filter.hpp"

namespace collidescope::bvh {
namespace {

void leaf_pair(const WorkItem& item, const MeshView& a, const Node& leaf_a, const MeshView& b,
               const Node& leaf_b, CandidateBuffer& candidates, TraversalStats& stats) {
    const std::uint32_t* ids_a = a.tree->triangle_ids.data() + leaf_a.index;
    const std::uint32_t* ids_b = b.tree->triangle_ids.data() + leaf_b.index;
    const Aabb* boxes_a = a.tree->leaf_boxes.data() + leaf_a.index;
    const Aabb* boxes_b = b.tree->leaf_boxes.data() + leaf_b.index;
    const bool same_object = item.obj_a == item.obj_b;
    const TriIndices* tris_a = a.tree->leaf_triangles.data() + leaf_a.index;
    const TriIndices* tris_b = b.tree->leaf_triangles.data() + leaf_b.index;
    const bool masked = !a.alive_triangles.empty() || !b.alive_triangles.empty();
    for (std::uint32_t i = 0; i < leaf_a.count; ++i) {
        if (masked && !a.alive_triangles.empty() && !a.alive_triangles[ids_a[i]]) continue;
        const Aabb& box_a = boxes_a[i];
        for (std::uint32_t j = 0; j < leaf_b.count; ++j) {
            if (masked && !b.alive_triangles.empty() && !b.alive_triangles[ids_b[j]]) continue;
            if (!overlaps(box_a, boxes_b[j])) continue;
            if (same_object && filter::adjacent_apart(tris_a[i], tris_b[j], a.vertices.data())) {
                ++stats.adjacent_apart;
                continue;
            }
            candidates.push_back(same_object ? make_pair_ordered(item.obj_a, ids_a[i], item.obj_b, ids_b[j])
                                             : TrianglePair{item.obj_a, ids_a[i], item.obj_b, ids_b[j]});
        }
    }
    stats.box_tests += std::uint64_t{leaf_a.count} * leaf_b.count;
}

}  // namespace

void step_pair(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats) {
    const MeshView& a = meshes[item.obj_a];
    const MeshView& b = meshes[item.obj_b];
    const Node& x = a.tree->nodes[item.node_a];
    const Node& y = b.tree->nodes[item.node_b];
    if ((!a.alive_nodes.empty() && !a.alive_nodes[item.node_a]) ||
        (!b.alive_nodes.empty() && !b.alive_nodes[item.node_b])) {
        return;  // a culled subtree (hybrid framework): nothing of it is left to test
    }
    ++stats.nodes_visited;
    ++stats.box_tests;
    if (!overlaps(x.box, y.box)) return;
    if (x.is_leaf() && y.is_leaf()) {
        const std::size_t before = candidates.size();
        leaf_pair(item, a, x, b, y, candidates, stats);
        stats.candidate_pairs += candidates.size() - before;
        return;
    }
    const bool split_a = !x.is_leaf() && (y.is_leaf() || x.box.half_area() >= y.box.half_area());
    const auto push_if_overlapping = [&](std::uint32_t node_a, std::uint32_t node_b) {
        ++stats.box_tests;
        if (overlaps(a.tree->nodes[node_a].box, b.tree->nodes[node_b].box))
            stack.push_back({item.obj_a, item.obj_b, node_a, node_b});
    };
    if (split_a) {
        push_if_overlapping(item.node_a + 1, item.node_b);
        push_if_overlapping(x.index, item.node_b);
    } else {
        push_if_overlapping(item.node_a, item.node_b + 1);
        push_if_overlapping(item.node_a, y.index);
    }
}

std::vector<std::uint8_t> percolate_alive(const Tree& tree, std::span<const std::uint8_t> alive_triangles) {
    std::vector<std::uint8_t> alive(tree.nodes.size(), 0);
    // Preorder: children come after their parent, so a backward sweep sees them first.
    for (std::size_t k = tree.nodes.size(); k-- > 0;) {
        const Node& node = tree.nodes[k];
        if (node.is_leaf()) {
            for (std::uint32_t i = 0; i < node.count && !alive[k]; ++i) {
                alive[k] = alive_triangles[tree.triangle_ids[node.index + i]];
            }
        } else {
            alive[k] = alive[k + 1] | alive[node.index];
        }
    }
    return alive;
}

}  // namespace collidescope::bvh
