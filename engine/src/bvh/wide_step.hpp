#pragma once
// One step of a tree-vs-tree walk on two wide layouts (wide_tree.hpp), for any caller
// (engine/src/bvh, private): the per-frame traversal between objects (traverse_wide.cpp) and
// the between-frames walk over swept trees (ccd/). An item is a pair of entries (wide nodes
// or leaves) whose boxes overlap. Two wide nodes: each child of B against A's four children,
// one vector comparison each; a wide node and a leaf: the leaf's box against the four
// children; two leaves: handed to the caller with their slot ranges, whose triangles it
// tests on their double boxes. Overlapping child pairs are handed to `push`, so every item
// is one the tests let through, and nothing is tested twice.

#include "bvh/bvh.hpp"

#include <bit>
#include <cstdint>
#include <cstring>

namespace collidescope::bvh::wide {

using Floats = float __attribute__((vector_size(16)));
using Mask = std::int32_t __attribute__((vector_size(16)));

inline Floats load(const std::array<float, 4>& lanes) {
    Floats v;
    std::memcpy(&v, lanes.data(), sizeof v);
    return v;
}

inline Floats splat(float x) { return Floats{x, x, x, x}; }

/// A leaf entry's float box, rounded outward from the union of its triangles' double boxes:
/// as its wide slot holds it (WideTree::leaf_box_at), computed only for a root leaf.
inline FloatBox leaf_box(const Tree& tree, std::uint32_t entry) {
    const std::uint32_t first = wide_leaf_first(entry), end = first + wide_leaf_count(entry);
    if (!tree.wide.nodes.empty()) [[likely]] return tree.wide.leaf_box_at[first];
    Aabb box = tree.leaf_boxes[first];
    for (std::uint32_t t = first + 1; t < end; ++t) box.grow(tree.leaf_boxes[t]);
    return {{round_down(box.lo[0]), round_down(box.lo[1]), round_down(box.lo[2])},
            {round_up(box.hi[0]), round_up(box.hi[1]), round_up(box.hi[2])}};
}

inline FloatBox child_box(const WideNode& node, int s) {
    return {{node.lo[0][s], node.lo[1][s], node.lo[2][s]}, {node.hi[0][s], node.hi[1][s], node.hi[2][s]}};
}

/// Bit s set when child s of `node` overlaps `box` (closed boxes). Unused slots are masked
/// off: their empty boxes (+inf, -inf) would pass against a box that rounds to infinities on
/// every axis (coordinates past float range), and a pushed empty entry is no node.
inline unsigned overlap_bits(const WideNode& node, const FloatBox& box) {
    Mask m = (load(node.lo[0]) <= splat(box.hi[0])) & (splat(box.lo[0]) <= load(node.hi[0]));
    m &= (load(node.lo[1]) <= splat(box.hi[1])) & (splat(box.lo[1]) <= load(node.hi[1]));
    m &= (load(node.lo[2]) <= splat(box.hi[2])) & (splat(box.lo[2]) <= load(node.hi[2]));
    const unsigned used = static_cast<unsigned>(node.child[0] != k_wide_empty) |
                          static_cast<unsigned>(node.child[1] != k_wide_empty) << 1 |
                          static_cast<unsigned>(node.child[2] != k_wide_empty) << 2 |
                          static_cast<unsigned>(node.child[3] != k_wide_empty) << 3;
    return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8)) & used;
}

/// Expands entries (entry_a of `a`, entry_b of `b`), whose boxes overlap: push(ea, eb) for
/// each overlapping child pair, or leaves(first_a, count_a, first_b, count_b) for two leaves
/// (slot ranges in leaf order). Returns the box tests made (a vector test counts four).
template <class Push, class Leaves>
std::uint64_t step(const Tree& a, std::uint32_t entry_a, const Tree& b, std::uint32_t entry_b, Push&& push,
                   Leaves&& leaves) {
    const bool leaf_a = is_wide_leaf(entry_a), leaf_b = is_wide_leaf(entry_b);
    if (leaf_a && leaf_b) {
        leaves(wide_leaf_first(entry_a), wide_leaf_count(entry_a), wide_leaf_first(entry_b), wide_leaf_count(entry_b));
        return 0;
    }
    if (leaf_b) {  // A's four children against B's leaf
        const WideNode& x = a.wide.nodes[entry_a];
        for (unsigned bits = overlap_bits(x, leaf_box(b, entry_b)); bits != 0; bits &= bits - 1) {
            push(x.child[std::countr_zero(bits)], entry_b);
        }
        return 4;
    }
    const WideNode& y = b.wide.nodes[entry_b];
    if (leaf_a) {  // A's leaf against B's four children
        const FloatBox box = leaf_box(a, entry_a);
        for (unsigned bits = overlap_bits(y, box); bits != 0; bits &= bits - 1) {
            push(entry_a, y.child[std::countr_zero(bits)]);
        }
        return 4;
    }
    const WideNode& x = a.wide.nodes[entry_a];
    std::uint64_t tests = 0;
    for (int t = 0; t < 4 && y.child[t] != k_wide_empty; ++t) {  // children fill slots from 0
        tests += 4;
        for (unsigned bits = overlap_bits(x, child_box(y, t)); bits != 0; bits &= bits - 1) {
            push(x.child[std::countr_zero(bits)], y.child[t]);
        }
    }
    return tests;
}

}  // namespace collidescope::bvh::wide
