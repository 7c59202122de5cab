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

// A leaf's float box: the union of its triangles' (the slots past its count masked off).
FloatBox leaf_box(const WideTree& wide, std::uint32_t entry) {
    const std::uint32_t first = wide_leaf_first(entry), end = first + wide_leaf_count(entry);
    FloatBox box{{k_inf, k_inf, k_inf}, {-k_inf, -k_inf, -k_inf}};
    for (std::uint32_t t = first; t < end; ++t) {
        for (int k = 0; k < 3; ++k) {
            box.lo[k] = wide.triangle_lo[k][t] < box.lo[k] ? wide.triangle_lo[k][t] : box.lo[k];
            box.hi[k] = wide.triangle_hi[k][t] > box.hi[k] ? wide.triangle_hi[k][t] : box.hi[k];
        }
    }
    return box;
}

FloatBox child_box(const WideNode& node, int s) {
    return {{node.lo[0][s], node.lo[1][s], node.lo[2][s]}, {node.hi[0][s], node.hi[1][s], node.hi[2][s]}};
}

/// Bit s set when child s of `node` overlaps `box` (closed boxes; empty slots never do).
unsigned overlap_bits(const WideNode& node, const FloatBox& box) {
    Mask m = (load(node.lo[0]) <= splat(box.hi[0])) & (splat(box.lo[0]) <= load(node.hi[0]));
    m &= (load(node.lo[1]) <= splat(box.hi[1])) & (splat(box.lo[1]) <= load(node.hi[1]));
    m &= (load(node.lo[2]) <= splat(box.hi[2])) & (splat(box.lo[2]) <= load(node.hi[2]));
    return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
}


/// Bit j set when triangle slot `slot + j` of `wide` overlaps `box` (the slots after a leaf's
/// last are masked off by the caller).
unsigned triangle_bits(const WideTree& wide, std::uint32_t slot, const FloatBox& box) {
    Mask m = (load(&wide.triangle_lo[0][slot]) <= splat(box.hi[0])) & (splat(box.lo[0]) <= load(&wide.triangle_hi[0][slot]));
    m &= (load(&wide.triangle_lo[1][slot]) <= splat(box.hi[1])) & (splat(box.lo[1]) <= load(&wide.triangle_hi[1][slot]));
    m &= (load(&wide.triangle_lo[2][slot]) <= splat(box.hi[2])) & (splat(box.lo[2]) <= load(&wide.triangle_hi[2][slot]));
    return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
}

// Two leaves of different objects: each triangle of A's against B's (at most four) in one
// vector test on the float boxes, then the double boxes of the pairs that pass, so the
// candidates are exactly the pairs whose closed double boxes overlap.
void wide_leaf_pair(const WorkItem& item, const Tree& a, const Tree& b, std::vector<TrianglePair>& candidates,
                    TraversalStats& stats) {
    const WideTree& wa = a.wide;
    const std::uint32_t first_a = wide_leaf_first(item.node_a), count_a = wide_leaf_count(item.node_a);
    const std::uint32_t first_b = wide_leaf_first(item.node_b), count_b = wide_leaf_count(item.node_b);
    const std::uint32_t end_b = first_b + count_b;
    for (std::uint32_t i = first_a; i < first_a + count_a; ++i) {
        const FloatBox box{{wa.triangle_lo[0][i], wa.triangle_lo[1][i], wa.triangle_lo[2][i]},
                           {wa.triangle_hi[0][i], wa.triangle_hi[1][i], wa.triangle_hi[2][i]}};
        for (std::uint32_t group = first_b; group < end_b; group += 4) {  // one group unless leaves exceed 4
            const unsigned lanes = end_b - group >= 4 ? 0xfu : (1u << (end_b - group)) - 1;
            for (unsigned bits = triangle_bits(b.wide, group, box) & lanes; bits != 0; bits &= bits - 1) {
                const std::uint32_t j = group + static_cast<std::uint32_t>(std::countr_zero(bits));
                if (!overlaps(a.leaf_boxes[i], b.leaf_boxes[j])) continue;
                candidates.push_back({item.obj_a, a.triangle_ids[i], item.obj_b, b.triangle_ids[j]});
            }
        }
    }
    stats.box_tests += std::uint64_t{count_a} * count_b;
}

}  // namespace

void step_wide(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               std::vector<TrianglePair>& candidates, TraversalStats& stats) {
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
        for (unsigned bits = overlap_bits(x, leaf_box(tree_b.wide, item.node_b)); bits != 0; bits &= bits - 1) {
            push(x.child[std::countr_zero(bits)], item.node_b);
        }
        return;
    }
    const WideNode& y = tree_b.wide.nodes[item.node_b];
    if (leaf_a) {  // A's leaf against B's four children
        stats.box_tests += 4;
        const FloatBox box = leaf_box(tree_a.wide, item.node_a);
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
