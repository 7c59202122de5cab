#pragma once
// The 4-wide layout of a tree for tree-vs-tree traversal between objects (engine/src/bvh,
// private): each wide node holds up to four children's boxes side by side in single
// precision, rounded outward, so that one child box of the other tree is tested against all
// four in one vector comparison (traverse_wide.cpp). Embree's rtcCollide gets its speed the
// same way (8-wide float nodes).
//
// Exactness: a float box rounded outward contains the double box it comes from, so a pair of
// leaves whose double boxes overlap has overlapping float ancestors and is always reached;
// the leaves' triangles are then tested on their double boxes, as the binary traversal does.
// The candidates are exactly the binary traversal's.

#include "collidescope/large_blocks.hpp"
#include "geometry/float32.hpp"

#include <array>
#include <limits>
#include <cstdint>
#include <vector>

namespace collidescope::bvh {

/// The trees' arrays: large ones in huge pages, kept for reuse (collidescope/large_blocks.hpp).
using collidescope::detail::LargeVector;

struct Tree;

/// A child entry naming a leaf of the binary tree: k_wide_leaf | first slot << 3 | (count -
/// 1), its triangles' range in leaf order, so that a leaf is reached without reading its
/// binary node (those reads were a third of the wide step's time on data set E). A tree with
/// a leaf of more than k_wide_max_leaf triangles, or k_wide_max_slots triangles or more, gets
/// no wide layout (the binary traversal serves it).
inline constexpr std::uint32_t k_wide_leaf = 1u << 31;
inline constexpr std::uint32_t k_wide_max_leaf = 8;
inline constexpr std::uint32_t k_wide_max_slots = 1u << 28;
/// An unused child slot (its box is empty: lo = +inf, hi = -inf, so it overlaps nothing).
inline constexpr std::uint32_t k_wide_empty = ~0u;

inline bool is_wide_leaf(std::uint32_t entry) { return (entry & k_wide_leaf) != 0 && entry != k_wide_empty; }
inline std::uint32_t wide_leaf(std::uint32_t first, std::uint32_t count) {
    return k_wide_leaf | first << 3 | (count - 1);
}
inline std::uint32_t wide_leaf_first(std::uint32_t entry) { return (entry & ~k_wide_leaf) >> 3; }
inline std::uint32_t wide_leaf_count(std::uint32_t entry) { return (entry & 7u) + 1; }

/// A box in single precision, rounded outward from its double box.
struct FloatBox {
    float lo[3];
    float hi[3];
};

/// One wide node: its children's boxes as lo[axis][child], hi[axis][child].
struct alignas(16) WideNode {
    std::array<std::array<float, 4>, 3> lo;
    std::array<std::array<float, 4>, 3> hi;
    /// A wide node index, a leaf (wide_leaf), or k_wide_empty; used slots come first.
    std::array<std::uint32_t, 4> child;
};

/// The wide layout of one Tree (Tree::wide), collapsed from its binary nodes and fitted to
/// its boxes on demand (fit_wide), so that only trees traversed against another object pay.
struct WideTree {
    LargeVector<WideNode> nodes;  ///< nodes[0] is the root's; empty when the root is a leaf
    /// Per binary node: 4 * wide node + slot of the wide slot it fills, or ~0 (refit writes
    /// each box it computes there, keeping the layout fitted once fit_wide has fitted it).
    LargeVector<std::uint32_t> slot_of;
    /// Each leaf's box as its wide slot holds it, at the leaf's first slot (leaf order): the
    /// leaf entries carry no box, and a leaf against a wide node needs one (recomputed from
    /// the triangles' boxes at every such step, it was 3% of a soup's interval). Fitted with
    /// the wide slots; unused when the root is a leaf (it has no slot).
    LargeVector<FloatBox> leaf_box_at;
    bool usable = false;  ///< false: the tree's leaves or size do not fit the leaf entries
    std::uint64_t built_for = ~std::uint64_t{0};   ///< the Tree::builds it was collapsed from
    std::uint64_t fitted_for = ~std::uint64_t{0};  ///< the Tree::fits its boxes come from
};

/// The entry of a non-empty tree's root: wide node 0, or the root leaf.
std::uint32_t wide_root(const Tree& tree);

/// True when `tree.wide` is usable and matches the tree's current build and boxes.
bool wide_fitted(const Tree& tree);

/// Collapses a non-empty tree's binary nodes into the wide layout (each wide node takes its
/// binary node's grandchildren, or a child that is a leaf), for the tree's current build;
/// reads no box. The layout is not fitted yet.
void prepare_wide(Tree& tree);

/// Brings `tree.wide` up to date: prepares it again after a build, then fits the wide nodes
/// bottom up: a leaf child from its triangles' double boxes (Tree::leaf_boxes), rounded
/// outward; a wide child as the union of its four float boxes (which contains the double
/// boxes below). From then on refit keeps the layout fitted on the way (refit.cpp), and a
/// build of a tree whose layout is in use prepares it within the build; a tree refit before
/// its first fit is fitted here.
void fit_wide(Tree& tree);

/// A float not above `value`, within a few float steps of it: the value moved down by 2^-22
/// of itself (plus 2^-147) before the conversion, which rounds by at most half a float step
/// (2^-24 relative, 2^-150 absolute below the normal range), so the result never exceeds
/// `value`. No branch on the rounding direction: an exact rounding's branch on it (as in
/// float32_below), inline and unpredictable, made fitting the wide layout cost more than the
/// refit itself. Values beyond float range, infinities and NaN take the exact path
/// (float32_below, out of line: geometry/float32.hpp).
inline float round_down(double value) {
    const double magnitude = value < 0 ? -value : value;
    if (magnitude < 1e38) [[likely]]
        return static_cast<float>(value - magnitude * 0x1p-22 - 0x1p-147);
    return float32_below(value);
}

/// A float not below `value`, within a few float steps of it (round_down's mirror).
inline float round_up(double value) {
    const double magnitude = value < 0 ? -value : value;
    if (magnitude < 1e38) [[likely]]
        return static_cast<float>(value + magnitude * 0x1p-22 + 0x1p-147);
    return float32_above(value);
}

}  // namespace collidescope::bvh
