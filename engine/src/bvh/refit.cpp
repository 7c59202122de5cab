// Refit: boxes recomputed bottom-up for new vertex positions (same topology). In preorder a
// node's children come after it, so walking a subtree's range backwards visits children
// first; the plan's subtrees go in parallel, then the top nodes, backwards.
// The SAH cost is summed on the way, per subtree and then in plan order (deterministic).

#include "bvh/bvh.hpp"

#include "pipeline/stopwatch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace collidescope::bvh {
namespace {

// The unnormalised SAH contribution of one node.
double node_cost(const Node& node) {
    return node.box.half_area() * (node.is_leaf() ? node.count : 1);
}

// Fits one node from its triangles (leaf) or children (inner node, already fitted).
void fit_node(Tree& tree, std::uint32_t index, std::span<const TriIndices> triangles,
              std::span<const Vec3> vertices) {
    Node& node = tree.nodes[index];
    Aabb box;
    if (node.is_leaf()) {
        const std::uint32_t* ids = tree.triangle_ids.data() + node.index;
        for (std::uint32_t k = 0; k < node.count; ++k) {
            const TriIndices& tri = triangles[ids[k]];
            box.grow(vertices[tri[0]]);
            box.grow(vertices[tri[1]]);
            box.grow(vertices[tri[2]]);
        }
    } else {
        box = tree.nodes[index + 1].box;
        box.grow(tree.nodes[node.index].box);
    }
    node.box = box;
}

double fit_range(Tree& tree, NodeRange range, std::span<const TriIndices> triangles,
                 std::span<const Vec3> vertices) {
    double cost = 0;
    for (std::uint32_t i = range.end; i-- > range.root;) {
        fit_node(tree, i, triangles, vertices);
        cost += node_cost(tree.nodes[i]);
    }
    return cost;
}

double normalise(const Tree& tree, double cost) {
    const double root_area = tree.nodes[0].box.half_area();
    if (!(root_area > 0) || !(cost < std::numeric_limits<double>::infinity())) {
        return static_cast<double>(tree.nodes.size());
    }
    return cost / root_area;
}

}  // namespace

RefitStats refit(Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> vertices) {
    const Stopwatch stopwatch;
    RefitStats stats;
    if (tree.empty()) return stats;
    const RefitPlan& plan = tree.refit_plan;
    std::vector<double> subtree_cost(plan.subtrees.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.subtrees.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
            subtree_cost[s] = fit_range(tree, plan.subtrees[s], triangles, vertices);
        }
    });
    double cost = 0;
    for (const double c : subtree_cost) cost += c;
    for (std::size_t k = plan.top.size(); k-- > 0;) {
        fit_node(tree, plan.top[k], triangles, vertices);
        cost += node_cost(tree.nodes[plan.top[k]]);
    }
    stats.nodes = static_cast<std::uint32_t>(tree.nodes.size());
    stats.sah_cost = normalise(tree, cost);
    stats.quality = tree.built_cost > 0 ? stats.sah_cost / tree.built_cost : 1.0;
    stats.ms = stopwatch.elapsed_ms();
    return stats;
}

double sah_cost(const Tree& tree) {
    if (tree.empty()) return 0;
    double cost = 0;
    for (const Node& node : tree.nodes) cost += node_cost(node);
    return normalise(tree, cost);
}

}  // namespace collidescope::bvh
