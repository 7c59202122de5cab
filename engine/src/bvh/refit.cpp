// Refit: boxes recomputed bottom-up for new vertex positions (same topology). The plan's
// subtrees go in parallel, each as its leaves (triangle slots in order) and then its inner
// nodes backwards in preorder (children before parents); then the top nodes, backwards.
// The SAH cost is summed on the way, per subtree and then in plan order (deterministic).

#include "bvh/bvh.hpp"
#include "bvh/surface_patches.hpp"

#include "stats/stopwatch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>
#include <cstring>

namespace collidescope::bvh {
namespace {

// The unnormalised SAH contribution of one node.
double node_cost(const Node& node) {
    return node.box.half_area() * (node.is_leaf() ? node.count : 1);
}

// x and y of a point or bound in one SIMD register (SSE2 on x86-64; GCC and Clang lower
// the vector type to scalars where there is none). `a < b ? a : b` on it compiles to minpd,
// the same exact min as on scalars.
using Pair = double __attribute__((vector_size(16)));

Pair load_xy(const double* p) {
    Pair pair;
    std::memcpy(&pair, p, sizeof pair);
    return pair;
}
Pair min(Pair a, Pair b) { return a < b ? a : b; }
Pair max(Pair a, Pair b) { return a > b ? a : b; }
double min(double a, double b) { return a < b ? a : b; }
double max(double a, double b) { return a > b ? a : b; }

// Running bounds in registers: x and y paired, z alone.
struct Bounds {
    Pair lo_xy, hi_xy;
    double lo_z, hi_z;

    static Bounds empty() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {Pair{inf, inf}, Pair{-inf, -inf}, inf, -inf};
    }
    void grow(const Bounds& b) {
        lo_xy = min(b.lo_xy, lo_xy), hi_xy = max(b.hi_xy, hi_xy);
        lo_z = min(b.lo_z, lo_z), hi_z = max(b.hi_z, hi_z);
    }
    void grow(const Aabb& b) { grow(Bounds{load_xy(b.lo.data()), load_xy(b.hi.data()), b.lo[2], b.hi[2]}); }
    // A triangle's bounds, its corners reduced pairwise: each bound is a chain of two
    // min/max operations, not three, and the triangles of a leaf overlap in flight.
    static Bounds of(const Vec3& a, const Vec3& b, const Vec3& c) {
        const Pair a_xy = load_xy(a.data()), b_xy = load_xy(b.data()), c_xy = load_xy(c.data());
        return {min(min(a_xy, b_xy), c_xy), max(max(a_xy, b_xy), c_xy),  //
                min(min(a[2], b[2]), c[2]), max(max(a[2], b[2]), c[2])};
    }
    /// Aabb::half_area of these bounds, computed the same way (the same double).
    double half_area() const {
        const double dx = hi_xy[0] - lo_xy[0], dy = hi_xy[1] - lo_xy[1], dz = hi_z - lo_z;
        if (!(dx >= 0 && dy >= 0 && dz >= 0)) return 0;
        return dx * dy + dy * dz + dz * dx;
    }
    void store(Aabb& box) const {
        std::memcpy(box.lo.data(), &lo_xy, sizeof lo_xy);
        std::memcpy(box.hi.data(), &hi_xy, sizeof hi_xy);
        box.lo[2] = lo_z;
        box.hi[2] = hi_z;
    }
};

// Writes a binary node's new box, rounded outward, into the wide slot that names it (the
// wide layout, kept fitted on the way: wide_tree.hpp); for a leaf (its first slot
// `leaf_first`), into WideTree::leaf_box_at too.
void write_wide_slot(WideTree& wide, std::uint32_t node, const Bounds& bounds, std::uint32_t leaf_first = ~0u) {
    const std::uint32_t at = wide.slot_of[node];
    if (at == ~0u) return;
    WideNode& target = wide.nodes[at >> 2];
    const std::uint32_t slot = at & 3u;
    const FloatBox rounded{{round_down(bounds.lo_xy[0]), round_down(bounds.lo_xy[1]), round_down(bounds.lo_z)},
                           {round_up(bounds.hi_xy[0]), round_up(bounds.hi_xy[1]), round_up(bounds.hi_z)}};
    for (int k = 0; k < 3; ++k) {
        target.lo[k][slot] = rounded.lo[k];
        target.hi[k][slot] = rounded.hi[k];
    }
    if (leaf_first != ~0u) wide.leaf_box_at[leaf_first] = rounded;
}

// Fits an inner node from its children (already fitted), with one store, and returns its
// node_cost from the registers. kSides (the tree has patches): its sides are its children's
// common sides. `wide` (may be null): the wide layout to keep fitted.
template <bool kSides>
double fit_inner(Tree& tree, std::uint32_t index, WideTree* wide) {
    Node& node = tree.nodes[index];
    if constexpr (kSides) {
        auto& sides = tree.patches.sides;
        sides[index] = sides[index + 1] & sides[node.index];
    }
    Bounds bounds = Bounds::empty();
    bounds.grow(tree.nodes[index + 1].box);
    bounds.grow(tree.nodes[node.index].box);
    bounds.store(node.box);
    if (wide != nullptr) write_wide_slot(*wide, index, bounds);
    return bounds.half_area();
}

// How many triangle slots ahead refit asks for vertices: leaf order is spatial, not the
// vertex array's order, so the hardware prefetcher cannot guess the gathers.
constexpr std::uint32_t kPrefetchSlots = 16;

// Where a triangle slot's box comes from: its corners at one position, its corners at two
// (between frames: the box of its positions at both ends, which holds it throughout a linear
// motion), or Tree::leaf_boxes as they stand.
enum class Slots { Corners, SweptCorners, Given };

// Fits one subtree and returns its nodes' node_cost sum, in two passes that never ask whether
// a node is a leaf: the triangle slots in order, storing each leaf's box at its last slot
// (flagged in the plan); then the inner nodes backwards, children before parents. The single
// backward walk it replaces branched on leaf or inner node per node, unpredictably, and
// called out and reloaded each box for its cost (docs/explanation/algorithms.md, "Refit").
// Exact: min and max only, so a box is the same whatever the order.
// kSides: also each leaf's patch sides (the triangles' common projected orientations).
// kSlots: each slot's box from `vertices`, from `vertices` and `to`, or as it is.
template <bool kSides, Slots kSlots = Slots::Corners>
double fit_subtree(Tree& tree, const RefitSubtree& subtree, std::span<const Vec3> vertices, WideTree* wide,
                   const Vec3* to = nullptr) {
    static_assert(!kSides || kSlots == Slots::Corners, "the sides come from one position's corners");
    const RefitPlan& plan = tree.refit_plan;
    Node* nodes = tree.nodes.data();
    const TriIndices* tris = tree.leaf_triangles.data();
    const std::uint32_t* leaf = plan.leaves.data() + subtree.leaf_begin;
    double cost = 0;
    std::uint8_t* sides = tree.patches.sides.data();
    Aabb* boxes = tree.leaf_boxes.data();
    std::uint8_t leaf_sides = 0x3f;
    Bounds bounds = Bounds::empty();
    std::uint32_t count = 0;
    for (std::uint32_t k = subtree.slot_begin; k < subtree.slot_end; ++k) {
        if constexpr (kSlots == Slots::Given) {
            bounds.grow(boxes[k]);
        } else {
            const TriIndices& ahead = tris[std::min(k + kPrefetchSlots, subtree.slot_end - 1)];
            for (const std::uint32_t v : ahead) __builtin_prefetch(vertices.data() + v);
            if constexpr (kSlots == Slots::SweptCorners) {
                for (const std::uint32_t v : ahead) __builtin_prefetch(to + v);
            }
            const Vec3 &a = vertices[tris[k][0]], &b = vertices[tris[k][1]], &c = vertices[tris[k][2]];
            Bounds triangle = Bounds::of(a, b, c);
            if constexpr (kSlots == Slots::SweptCorners) triangle.grow(Bounds::of(to[tris[k][0]], to[tris[k][1]], to[tris[k][2]]));
            triangle.store(boxes[k]);
            bounds.grow(triangle);
            if constexpr (kSides) leaf_sides &= triangle_sides(a, b, c);
        }
        ++count;
        if (plan.leaf_ends[k]) {
            if constexpr (kSides) {
                sides[*leaf] = leaf_sides;
                leaf_sides = 0x3f;
            }
            if (wide != nullptr) write_wide_slot(*wide, *leaf, bounds, k + 1 - count);
            bounds.store(nodes[*leaf++].box);
            cost += bounds.half_area() * count;
            bounds = Bounds::empty();
            count = 0;
        }
    }
    for (std::uint32_t j = subtree.inner_end; j-- > subtree.inner_begin;) {
        cost += fit_inner<kSides>(tree, plan.inner[j], wide);
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

// The refit of the plan's subtrees in parallel and then its top, each slot's box as kSlots
// says, without the patches' sides or a wide layout, which goes stale: between frames, writing
// the layout's slots on the way made the refit slower than the refit and a pass of fit_wide
// after it (data set E4: 0.87 of the time with the separate pass, A 0.93, alternated runs).
template <Slots kSlots>
RefitStats fit_plain(Tree& tree, std::span<const Vec3> from, std::span<const Vec3> to) {
    const Stopwatch stopwatch;
    RefitStats stats;
    if (tree.empty()) return stats;
    const RefitPlan& plan = tree.refit_plan;
    std::vector<double> subtree_cost(plan.subtrees.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.subtrees.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
            subtree_cost[s] = fit_subtree<false, kSlots>(tree, plan.subtrees[s], from, nullptr, to.data());
        }
    });
    double cost = 0;
    for (const double c : subtree_cost) cost += c;
    for (std::size_t k = plan.top.size(); k-- > 0;) cost += fit_inner<false>(tree, plan.top[k], nullptr);
    ++tree.fits;  // a wide layout is stale now
    stats.nodes = static_cast<std::uint32_t>(tree.nodes.size());
    stats.sah_cost = normalise(tree, cost);
    stats.quality = tree.built_cost > 0 ? stats.sah_cost / tree.built_cost : 1.0;
    stats.ms = stopwatch.elapsed_ms();
    return stats;
}

}  // namespace

RefitStats refit_swept(Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> from,
                       std::span<const Vec3> to) {
    assert(tree.empty() || (triangles.size() == tree.leaf_triangles.size() && from.size() == to.size()));
    (void)triangles;
    return fit_plain<Slots::SweptCorners>(tree, from, to);
}

RefitStats fit_to_leaf_boxes(Tree& tree) { return fit_plain<Slots::Given>(tree, {}, {}); }

RefitStats refit(Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> vertices) {
    const Stopwatch stopwatch;
    RefitStats stats;
    if (tree.empty()) return stats;
    // The tree's own copy of the triangles (leaf_triangles) is what refit reads; `triangles`
    // must be the topology it was built for.
    assert(triangles.size() == tree.leaf_triangles.size());
    (void)triangles;
    const RefitPlan& plan = tree.refit_plan;
    const bool with_sides = !tree.patches.empty();
    // A wide layout fitted once since its collapse is kept fitted here, on the way (its
    // separate fit cost as much as this refit on data set E).
    WideTree* wide = tree.wide.usable && tree.wide.built_for == tree.builds && tree.wide.fitted_for != ~std::uint64_t{0}
                         ? &tree.wide
                         : nullptr;
    std::vector<double> subtree_cost(plan.subtrees.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.subtrees.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
            subtree_cost[s] = with_sides ? fit_subtree<true>(tree, plan.subtrees[s], vertices, wide)
                                         : fit_subtree<false>(tree, plan.subtrees[s], vertices, wide);
        }
    });
    double cost = 0;
    for (const double c : subtree_cost) cost += c;
    for (std::size_t k = plan.top.size(); k-- > 0;) {
        cost += with_sides ? fit_inner<true>(tree, plan.top[k], wide) : fit_inner<false>(tree, plan.top[k], wide);
    }
    ++tree.fits;  // the boxes changed: a wide layout not fitted on the way is stale
    if (wide != nullptr) wide->fitted_for = tree.fits;
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
