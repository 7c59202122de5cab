// The tree validator: a slow, obvious walk over every node (serial, no shortcuts).

#include "bvh/validate_tree.hpp"

#include <algorithm>

namespace collidescope::bvh {
namespace {

class Validator {
public:
    Validator(const Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
              const ValidateOptions& options)
        : m_tree(tree), m_triangles(triangles), m_vertices(vertices), m_options(options),
          m_reached(tree.nodes.size(), 0), m_seen(triangles.size(), 0) {}

    std::vector<std::string> run() {
        if (m_tree.empty()) {
            if (!m_triangles.empty()) fail("empty tree for " + std::to_string(m_triangles.size()) + " triangles");
            return m_errors;
        }
        if (m_tree.triangle_ids.size() != m_triangles.size()) {
            fail("triangle_ids has " + std::to_string(m_tree.triangle_ids.size()) + " entries for " +
                 std::to_string(m_triangles.size()) + " triangles");
            return m_errors;
        }
        visit(0, static_cast<std::uint32_t>(m_tree.nodes.size()));
        check_totals();
        check_plan();
        return m_errors;
    }

private:
    void fail(std::string message) {
        if (m_errors.size() < 20) m_errors.push_back(std::move(message));
    }

    // Node `index` owns the preorder range [index, end).
    void visit(std::uint32_t index, std::uint32_t end) {
        if (index >= end || index >= m_tree.nodes.size()) {
            fail("node " + std::to_string(index) + " outside its range (end " + std::to_string(end) + ")");
            return;
        }
        ++m_reached[index];
        const Node& node = m_tree.nodes[index];
        if (node.is_leaf()) {
            if (index + 1 != end) fail("leaf " + std::to_string(index) + " does not end its range");
            visit_leaf(index, node);
            return;
        }
        const std::uint32_t right = node.index;
        if (!(index + 1 < right && right < end)) {
            fail("node " + std::to_string(index) + ": right child " + std::to_string(right) + " outside (" +
                 std::to_string(index + 1) + ", " + std::to_string(end) + ")");
            return;
        }
        check_child(index, index + 1);
        check_child(index, right);
        if (m_options.tight) {
            Aabb expected = m_tree.nodes[index + 1].box;
            expected.grow(m_tree.nodes[right].box);
            if (!(expected == node.box)) fail("node " + std::to_string(index) + ": box is not its children's union");
        }
        ++m_inner;
        visit(index + 1, right);
        visit(right, end);
    }

    void check_child(std::uint32_t parent, std::uint32_t child) {
        if (!contains(m_tree.nodes[parent].box, m_tree.nodes[child].box)) {
            fail("node " + std::to_string(child) + ": box not inside its parent " + std::to_string(parent));
        }
    }

    void visit_leaf(std::uint32_t index, const Node& node) {
        ++m_leaves;
        if (node.count > m_options.max_leaf_size) {
            fail("leaf " + std::to_string(index) + " holds " + std::to_string(node.count) + " triangles");
        }
        if (node.index != m_next_slot) {
            fail("leaf " + std::to_string(index) + " starts at slot " + std::to_string(node.index) +
                 ", expected " + std::to_string(m_next_slot));
        }
        m_next_slot = node.index + node.count;
        if (m_next_slot > m_tree.triangle_ids.size()) {
            fail("leaf " + std::to_string(index) + " runs past triangle_ids");
            return;
        }
        Aabb fitted;
        for (std::uint32_t k = node.index; k < m_next_slot; ++k) {
            const std::uint32_t tri = m_tree.triangle_ids[k];
            if (tri >= m_triangles.size()) {
                fail("leaf " + std::to_string(index) + ": triangle " + std::to_string(tri) + " out of range");
                continue;
            }
            ++m_seen[tri];
            if (k >= m_tree.leaf_triangles.size() || m_tree.leaf_triangles[k] != m_triangles[tri]) {
                fail("leaf_triangles[" + std::to_string(k) + "] is not triangle " + std::to_string(tri));
            }
            const Aabb box = triangle_box(m_triangles, m_vertices, tri);
            // The traversal's leaf tests read the stored box: it must be the triangle's own
            // (a stale one could drop a pair), exactly; not tight (a swept tree): hold it.
            if (k >= m_tree.leaf_boxes.size() ||
                !(m_options.tight ? m_tree.leaf_boxes[k] == box : contains(m_tree.leaf_boxes[k], box))) {
                fail("leaf_boxes[" + std::to_string(k) + (m_options.tight ? "] is not" : "] does not hold") +
                     " the box of triangle " + std::to_string(tri));
            }
            fitted.grow(box);
            if (!contains(node.box, box)) {
                fail("leaf " + std::to_string(index) + ": triangle " + std::to_string(tri) + " sticks out of its box");
            }
        }
        if (m_options.tight && !(fitted == node.box)) fail("leaf " + std::to_string(index) + ": box is not tight");
    }

    void check_totals() {
        for (std::size_t i = 0; i < m_reached.size(); ++i) {
            if (m_reached[i] != 1) fail("node " + std::to_string(i) + " reached " + std::to_string(m_reached[i]) + " times");
        }
        for (std::size_t t = 0; t < m_seen.size(); ++t) {
            if (m_seen[t] != 1) fail("triangle " + std::to_string(t) + " in " + std::to_string(m_seen[t]) + " leaves");
        }
        if (m_tree.nodes.size() != 2 * m_leaves - 1 || m_inner + 1 != m_leaves) {
            fail(std::to_string(m_tree.nodes.size()) + " nodes for " + std::to_string(m_leaves) + " leaves");
        }
        if (m_next_slot != m_tree.triangle_ids.size()) fail("leaves do not cover triangle_ids");
    }

    // The refit plan's subtrees and top nodes together cover every node exactly once.
    void check_plan() {
        std::vector<int> covered(m_tree.nodes.size(), 0);
        for (const RefitSubtree& subtree : m_tree.refit_plan.subtrees) {
            const NodeRange range = subtree.nodes;
            for (std::uint32_t i = range.root; i < range.end && i < covered.size(); ++i) ++covered[i];
        }
        for (const std::uint32_t top : m_tree.refit_plan.top) {
            if (top < covered.size()) ++covered[top];
        }
        if (std::any_of(covered.begin(), covered.end(), [](int c) { return c != 1; })) {
            fail("the refit plan does not cover every node exactly once");
            return;
        }
        check_plan_walks();
    }

    // What refit walks per subtree, recomputed node by node: the leaves in preorder with their
    // slots and last-slot flags, the inner nodes in preorder.
    void check_plan_walks() {
        const RefitPlan& plan = m_tree.refit_plan;
        if (plan.leaf_ends.size() != m_tree.triangle_ids.size()) {
            fail("the refit plan's leaf_ends has " + std::to_string(plan.leaf_ends.size()) + " slots");
            return;
        }
        std::vector<std::uint8_t> ends(m_tree.triangle_ids.size(), 0);
        std::vector<std::uint32_t> leaves;
        std::vector<std::uint32_t> inner;
        for (std::size_t s = 0; s < plan.subtrees.size(); ++s) {
            const RefitSubtree& subtree = plan.subtrees[s];
            const std::string name = "refit subtree " + std::to_string(s);
            if (subtree.leaf_begin != leaves.size()) fail(name + ": leaf_begin " + std::to_string(subtree.leaf_begin));
            if (subtree.inner_begin != inner.size()) fail(name + ": inner_begin " + std::to_string(subtree.inner_begin));
            std::uint32_t slot_begin = ~0u;
            std::uint32_t slot_end = 0;
            for (std::uint32_t i = subtree.nodes.root; i < subtree.nodes.end; ++i) {
                const Node& node = m_tree.nodes[i];
                if (!node.is_leaf()) {
                    inner.push_back(i);
                    continue;
                }
                leaves.push_back(i);
                slot_begin = std::min(slot_begin, node.index);
                slot_end = node.index + node.count;
                if (slot_end - 1 < ends.size()) ends[slot_end - 1] = 1;
            }
            if (subtree.slot_begin != slot_begin || subtree.slot_end != slot_end) {
                fail(name + ": slots [" + std::to_string(subtree.slot_begin) + ", " + std::to_string(subtree.slot_end) +
                     "), its leaves hold [" + std::to_string(slot_begin) + ", " + std::to_string(slot_end) + ")");
            }
            if (subtree.inner_end != inner.size()) fail(name + ": inner_end " + std::to_string(subtree.inner_end));
        }
        if (!std::ranges::equal(plan.leaves, leaves)) fail("the refit plan's leaves are not the tree's leaves in preorder");
        if (!std::ranges::equal(plan.inner, inner)) fail("the refit plan's inner nodes are not the subtrees' inner nodes in preorder");
        if (!std::ranges::equal(plan.leaf_ends, ends)) fail("the refit plan's leaf_ends do not mark the leaves' last slots");
    }

    const Tree& m_tree;
    std::span<const TriIndices> m_triangles;
    std::span<const Vec3> m_vertices;
    const ValidateOptions& m_options;
    std::vector<int> m_reached;
    std::vector<int> m_seen;
    std::vector<std::string> m_errors;
    std::uint32_t m_next_slot = 0;
    std::size_t m_leaves = 0;
    std::size_t m_inner = 0;
};

}  // namespace

std::vector<std::string> validate(const Tree& tree, std::span<const TriIndices> triangles,
                                  std::span<const Vec3> vertices, const ValidateOptions& options) {
    return Validator(tree, triangles, vertices, options).run();
}

}  // namespace collidescope::bvh
