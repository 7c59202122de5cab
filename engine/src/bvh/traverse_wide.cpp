// Tree-vs-tree traversal step on the wide layouts (wide_tree.hpp): an item is a pair of
// entries (wide nodes or binary leaves) whose boxes overlap. Two wide nodes: each child of
// B against A's four children, one vector comparison each; a wide node and a leaf: the
// leaf's box against the four children; two leaves: their triangles (leaf_pair, on the
// double boxes). Overlapping child pairs go onto the stack, so every popped item is one the
// tests let through, and nothing is tested twice.

#include "bvh/traverse.hpp"

#include <bit>
#include <cstring>
#include <limits>

namespace collidescope::bvh {
namespace {

using Floats = float __attribute__((vector_size(16)));
using Mask = std::int32_t __attribute__((vector_size(16)));

Floats load(const float* lanes) {
    Floats v;
    std::memcpy(&v, lanes, sizeof v);
    return v;
}

Floats load(const std::array<float, 4>& lanes) { return load(lanes.data()); }

Floats splat(float x) { return Floats{x, x, x, x}; }

constexpr float k_inf = std::numeric_limits<float>::infinity();

/// A box in single precision, rounded outward from its double box.
struct FloatBox {
    float lo[3];
    float hi[3];
};

// A leaf's float box, rounded outward from the union of its triangles' double boxes.
FloatBox leaf_box(const Tree& tree, std::uint32_t entry) {
    const std::uint32_t first = wide_leaf_first(entry), end = first + wide_leaf_count(entry);
    Aabb box = tree.leaf_boxes[first];
    for (std::uint32_t t = first + 1; t < end; ++t) box.grow(tree.leaf_boxes[t]);
    return {{round_down(box.lo[0]), round_down(box.lo[1]), round_down(box.lo[2])},
            {round_up(box.hi[0]), round_up(box.hi[1]), round_up(box.hi[2])}};
}

FloatBox child_box(const WideNode& node, int s) {
    return {{node.lo[0][s], node.lo[1][s], node.lo[2][s]}, {node.hi[0][s], node.hi[1][s], node.hi[2][s]}};
}

/// Bit s set when child s of `node` overlaps `box` (closed boxes). Unused slots are masked
/// off: their empty boxes (+inf, -inf) would pass against a box that rounds to infinities on
/// every axis (coordinates past float range), and a pushed empty entry is no node.
unsigned overlap_bits(const WideNode& node, const FloatBox& box) {
    Mask m = (load(node.lo[0]) <= splat(box.hi[0])) & (splat(box.lo[0]) <= load(node.hi[0]));
    m &= (load(node.lo[1]) <= splat(box.hi[1])) & (splat(box.lo[1]) <= load(node.hi[1]));
    m &= (load(node.lo[2]) <= splat(box.hi[2])) & (splat(box.lo[2]) <= load(node.hi[2]));
    const unsigned used = static_cast<unsigned>(node.child[0] != k_wide_empty) |
                          static_cast<unsigned>(node.child[1] != k_wide_empty) << 1 |
                          static_cast<unsigned>(node.child[2] != k_wide_empty) << 2 |
                          static_cast<unsigned>(node.child[3] != k_wide_empty) << 3;
    return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8)) & used;
}


// Two leaves of different objects: every triangle pair on the double boxes (the leaf entries
// carry the slot ranges, so no binary node is read), the candidates exactly the pairs whose
// closed boxes overlap.
void wide_leaf_pair(const WorkItem& item, const Tree& a, const Tree& b, CandidateBuffer& candidates,
                    TraversalStats& stats) {
    const std::uint32_t first_a = wide_leaf_first(item.node_a), count_a = wide_leaf_count(item.node_a);
    const std::uint32_t first_b = wide_leaf_first(item.node_b), count_b = wide_leaf_count(item.node_b);
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
    const MeshView& a = meshes[item.obj_a];
    const MeshView& b = meshes[item.obj_b];
    const Tree& tree_a = *a.tree;
    const Tree& tree_b = *b.tree;
    ++stats.nodes_visited;
    const auto push = [&](std::uint32_t entry_a, std::uint32_t entry_b) {
        stack.push_back({item.obj_a, item.obj_b, entry_a, entry_b, true});
    };
    const bool leaf_a = is_wide_leaf(item.node_a), leaf_b = is_wide_leaf(item.node_b);
    if (leaf_a && leaf_b) {
        const std::size_t before = candidates.size();
        wide_leaf_pair(item, tree_a, tree_b, candidates, stats);
        stats.candidate_pairs += candidates.size() - before;
        return;
    }
    if (leaf_b) {  // A's four children against B's leaf
        const WideNode& x = tree_a.wide.nodes[item.node_a];
        stats.box_tests += 4;
        for (unsigned bits = overlap_bits(x, leaf_box(tree_b, item.node_b)); bits != 0; bits &= bits - 1) {
            push(x.child[std::countr_zero(bits)], item.node_b);
        }
        return;
    }
    const WideNode& y = tree_b.wide.nodes[item.node_b];
    if (leaf_a) {  // A's leaf against B's four children
        stats.box_tests += 4;
        const FloatBox box = leaf_box(tree_a, item.node_a);
        for (unsigned bits = overlap_bits(y, box); bits != 0; bits &= bits - 1) {
            push(item.node_a, y.child[std::countr_zero(bits)]);
        }
        return;
    }
    const WideNode& x = tree_a.wide.nodes[item.node_a];
    for (int t = 0; t < 4 && y.child[t] != k_wide_empty; ++t) {  // children fill slots from 0
        stats.box_tests += 4;
        for (unsigned bits = overlap_bits(x, child_box(y, t)); bits != 0; bits &= bits - 1) {
            push(x.child[std::countr_zero(bits)], y.child[t]);
        }
    }
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
