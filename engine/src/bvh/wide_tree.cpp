// The wide layout: collapse (after a build) and fit (after a refit).

#include "bvh/wide_tree.hpp"

#include "bvh/bvh.hpp"

#include <limits>

namespace collidescope::bvh {
namespace {

// Collapses the binary tree into wide nodes, iteratively (an LBVH over equal codes can be
// deep): a wide node takes its binary node's grandchildren, or a child itself where that is
// a leaf (two levels merged, as Embree's BVH4 builders do from a binary split). No box is
// read, so a build collapses before its refit and the refit fits the layout on the way.
// False when a leaf is too large for a leaf entry (the layout is then unusable).
bool collapse(const Tree& tree, WideTree& wide) {
    wide.nodes.clear();
    // At most one wide node per binary inner node: reserved (untouched until written), so the
    // vector never grows by copying into fresh memory.
    wide.nodes.reserve(tree.nodes.size() / 2);
    wide.slot_of.assign(tree.nodes.size(), ~0u);
    struct Pending {
        std::uint32_t binary;  // an inner node of the binary tree
        std::uint32_t parent;  // the wide node whose child it becomes, or ~0 for the root
        std::uint32_t slot;
    };
    std::vector<Pending> stack{{0, ~0u, 0}};
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::uint32_t>(wide.nodes.size());
        if (pending.parent != ~0u) wide.nodes[pending.parent].child[pending.slot] = index;
        std::array<std::uint32_t, 4> slots{};
        std::uint32_t used = 0;
        for (const std::uint32_t child : {pending.binary + 1, tree.nodes[pending.binary].index}) {
            const Node& node = tree.nodes[child];
            if (node.is_leaf()) {
                slots[used++] = child;
            } else {
                slots[used++] = child + 1;
                slots[used++] = node.index;
            }
        }
        WideNode node{};
        node.child.fill(k_wide_empty);
        for (int k = 0; k < 3; ++k) {  // empty boxes until fitted; unused slots stay empty
            node.lo[k].fill(std::numeric_limits<float>::infinity());
            node.hi[k].fill(-std::numeric_limits<float>::infinity());
        }
        wide.nodes.push_back(node);
        for (std::uint32_t s = 0; s < used; ++s) {
            wide.slot_of[slots[s]] = 4 * index + s;
            const Node& child = tree.nodes[slots[s]];
            if (child.is_leaf()) {
                if (child.count > k_wide_max_leaf) return false;
                wide.nodes[index].child[s] = wide_leaf(child.index, child.count);
            } else {
                stack.push_back({slots[s], index, s});
            }
        }
    }
    return true;
}

// Lane minimum and maximum of a wide child's four boxes (`a < b ? a : b`: no NaN reaches a fit).
float lane_min(const std::array<float, 4>& v) {
    const float a = v[0] < v[1] ? v[0] : v[1], b = v[2] < v[3] ? v[2] : v[3];
    return a < b ? a : b;
}
float lane_max(const std::array<float, 4>& v) {
    const float a = v[0] > v[1] ? v[0] : v[1], b = v[2] > v[3] ? v[2] : v[3];
    return a > b ? a : b;
}

// Fits wide node `w` from its children: leaves from their triangles' double boxes, rounded
// outward; wide children (fitted before it: they come after it in the array) as the union
// of their four boxes.
void fit_node(const Tree& tree, WideTree& wide, std::size_t w) {
    WideNode& node = wide.nodes[w];
    for (int s = 0; s < 4; ++s) {
        const std::uint32_t child = node.child[s];
        if (child == k_wide_empty) continue;  // stays empty
        if (is_wide_leaf(child)) {
            const std::uint32_t first = wide_leaf_first(child), end = first + wide_leaf_count(child);
            Aabb box = tree.leaf_boxes[first];
            for (std::uint32_t t = first + 1; t < end; ++t) box.grow(tree.leaf_boxes[t]);
            FloatBox& rounded = wide.leaf_box_at[first];
            for (int k = 0; k < 3; ++k) {
                node.lo[k][s] = rounded.lo[k] = round_down(box.lo[k]);
                node.hi[k][s] = rounded.hi[k] = round_up(box.hi[k]);
            }
        } else {
            const WideNode& below = wide.nodes[child];
            for (int k = 0; k < 3; ++k) {
                node.lo[k][s] = lane_min(below.lo[k]);
                node.hi[k][s] = lane_max(below.hi[k]);
            }
        }
    }
}

}  // namespace

std::uint32_t wide_root(const Tree& tree) {
    const Node& root = tree.nodes[0];
    return root.is_leaf() ? wide_leaf(root.index, root.count) : 0;
}

bool wide_fitted(const Tree& tree) {
    return !tree.empty() && tree.wide.usable && tree.wide.built_for == tree.builds && tree.wide.fitted_for == tree.fits;
}

void prepare_wide(Tree& tree) {
    WideTree& wide = tree.wide;
    wide.built_for = tree.builds;
    wide.fitted_for = ~std::uint64_t{0};
    const Node& root = tree.nodes[0];
    if (tree.leaf_boxes.size() >= k_wide_max_slots) {
        wide.usable = false;
    } else if (root.is_leaf()) {
        wide.nodes.clear();
        wide.slot_of.assign(tree.nodes.size(), ~0u);
        wide.usable = root.count <= k_wide_max_leaf;
    } else {
        wide.usable = collapse(tree, wide);
    }
    wide.leaf_box_at.resize(wide.usable ? tree.leaf_boxes.size() : 0);
}

void fit_wide(Tree& tree) {
    WideTree& wide = tree.wide;
    if (tree.empty()) {
        wide = WideTree{};
        return;
    }
    if (wide.built_for != tree.builds) prepare_wide(tree);
    if (!wide.usable || wide.fitted_for == tree.fits) return;
    for (std::size_t w = wide.nodes.size(); w-- > 0;) fit_node(tree, wide, w);
    wide.fitted_for = tree.fits;
}

}  // namespace collidescope::bvh
