// Refit: boxes recomputed bottom-up for new vertex positions (same topology). In preorder a
// node's children come after it, so walking a subtree's range backwards visits children
// first; the plan's subtrees go in parallel, then the top nodes, backwards.
// The SAH cost is summed on the way, per subtree and then in plan order (deterministic).

#include "bvh/bvh.hpp"

#include "pipeline/stopwatch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cassert>

namespace collidescope::bvh {
namespace {

// The unnormalised SAH contribution of one node.
double node_cost(const Node& node) {
    return node.box.half_area() * (node.is_leaf() ? node.count : 1);
}

// Fits one node from its triangles (leaf) or children (inner node, already fitted). Plain
// locals and one store per node: the compiler keeps the six bounds in registers.
void fit_node(Tree& tree, std::uint32_t index, std::span<const Vec3> vertices) {
    Node& node = tree.nodes[index];
    constexpr double inf = std::numeric_limits<double>::infinity();
    double lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf;
    const auto grow = [&](const double* lo, const double* hi) {
        lo0 = lo[0] < lo0 ? lo[0] : lo0;
        lo1 = lo[1] < lo1 ? lo[1] : lo1;
        lo2 = lo[2] < lo2 ? lo[2] : lo2;
        hi0 = hi[0] > hi0 ? hi[0] : hi0;
        hi1 = hi[1] > hi1 ? hi[1] : hi1;
        hi2 = hi[2] > hi2 ? hi[2] : hi2;
    };
    if (node.is_leaf()) {
        const TriIndices* tris = tree.leaf_triangles.data() + node.index;
        for (std::uint32_t k = 0; k < node.count; ++k) {
            for (const std::uint32_t v : tris[k]) grow(vertices[v].data(), vertices[v].data());
        }
    } else {
        const Aabb& left = tree.nodes[index + 1].box;
        const Aabb& right = tree.nodes[node.index].box;
        grow(left.lo.data(), left.hi.data());
        grow(right.lo.data(), right.hi.data());
    }
    node.box.lo = {lo0, lo1, lo2};
    node.box.hi = {hi0, hi1, hi2};
}

double fit_range(Tree& tree, NodeRange range, std::span<const Vec3> vertices) {
    double cost = 0;
    for (std::uint32_t i = range.end; i-- > range.root;) {
        fit_node(tree, i, vertices);
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
    // The tree's own copy of the triangles (leaf_triangles) is what refit reads; `triangles`
    // must be the topology it was built for.
    assert(triangles.size() == tree.leaf_triangles.size());
    (void)triangles;
    const RefitPlan& plan = tree.refit_plan;
    std::vector<double> subtree_cost(plan.subtrees.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.subtrees.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
            subtree_cost[s] = fit_range(tree, plan.subtrees[s], vertices);
        }
    });
    double cost = 0;
    for (const double c : subtree_cost) cost += c;
    for (std::size_t k = plan.top.size(); k-- > 0;) {
        fit_node(tree, plan.top[k], vertices);
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
