// build_tree: per-triangle input, one of the builders, the preorder layout, the refit plan,
// then a refit for the boxes (both builders leave boxes to it).

#include "bvh/build_internal.hpp"
#include "bvh/surface_patches.hpp"

#include "stats/stopwatch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <numeric>

namespace collidescope::bvh {
namespace detail {

void make_build_input(std::span<const TriIndices> triangles, std::span<const Vec3> vertices, bool with_boxes,
                      BuildInput& input, std::span<const Vec3> to) {
    input.boxes.resize(with_boxes ? triangles.size() : 0);
    input.centroids.resize(triangles.size());
    const bool swept = !to.empty();
    input.centroid_bounds = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, triangles.size(), 4096), Aabb{},
        [&](const tbb::blocked_range<std::size_t>& range, Aabb bounds) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
                Aabb box = triangle_box(triangles, vertices, static_cast<std::uint32_t>(t));
                if (swept) box.grow(triangle_box(triangles, to, static_cast<std::uint32_t>(t)));
                if (with_boxes) input.boxes[t] = box;
                Vec3 c;
                for (int k = 0; k < 3; ++k) c[k] = 0.5 * box.lo[k] + 0.5 * box.hi[k];
                input.centroids[t] = {c[0], c[1], c[2]};
                bounds.grow(c);
            }
            return bounds;
        },
        [](Aabb a, const Aabb& b) { a.grow(b); return a; });  // min/max: order-independent
}

}  // namespace detail

namespace {

// Copies the raw tree into `nodes`, in preorder (left child next, right child in `index`),
// iteratively, and measures its depth on the way (a separate recursive walk cost 4% of an
// LBVH build).
void to_preorder(const detail::RawTree& raw, LargeVector<Node>& nodes, std::uint32_t& depth) {
    nodes.clear();
    nodes.reserve(raw.used.load());
    struct Item {
        std::uint32_t raw;
        std::uint32_t parent;  // preorder index of the parent whose right child this is, or ~0
        std::uint32_t depth;   // 1 at the root
    };
    std::vector<Item> stack{{0, ~0u, 1}};
    depth = 0;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        depth = std::max(depth, item.depth);
        const auto index = static_cast<std::uint32_t>(nodes.size());
        if (item.parent != ~0u) nodes[item.parent].index = index;
        const detail::RawNode& node = raw.nodes[item.raw];
        Node out;
        out.count = node.count;
        out.index = node.count != 0 ? node.first : 0;
        nodes.push_back(out);
        if (node.count == 0) {
            stack.push_back({node.first + 1, index, item.depth + 1});  // right: after the left subtree
            stack.push_back({node.first, ~0u, item.depth + 1});
        }
    }
}

// Cuts the tree into subtrees of at most `grain` nodes (refit in parallel) below a top part.
void plan_range(const Tree& tree, NodeRange range, std::uint32_t grain, RefitPlan& plan) {
    const Node& node = tree.nodes[range.root];
    if (node.is_leaf() || range.end - range.root <= grain) {
        plan.subtrees.push_back({range});
        return;
    }
    plan.top.push_back(range.root);
    plan_range(tree, {range.root + 1, node.index}, grain, plan);
    plan_range(tree, {node.index, range.end}, grain, plan);
}

// The refit plan, in `plan`: the cut, then each subtree's leaves, slots and inner nodes.
// Subtrees come left to right, so their leaves, and so their slots, follow each other.
void plan_refit(const Tree& tree, std::uint32_t grain, RefitPlan& plan) {
    plan.subtrees.clear();
    plan.top.clear();
    plan.leaves.clear();
    plan.inner.clear();
    plan_range(tree, {0, static_cast<std::uint32_t>(tree.nodes.size())}, grain, plan);
    plan.leaf_ends.assign(tree.leaf_triangles.size(), 0);
    std::uint32_t slot = 0;
    for (RefitSubtree& subtree : plan.subtrees) {
        subtree.slot_begin = slot;
        subtree.leaf_begin = static_cast<std::uint32_t>(plan.leaves.size());
        subtree.inner_begin = static_cast<std::uint32_t>(plan.inner.size());
        for (std::uint32_t i = subtree.nodes.root; i < subtree.nodes.end; ++i) {
            const Node& node = tree.nodes[i];
            if (node.is_leaf()) {
                plan.leaves.push_back(i);
                slot = node.index + node.count;
                plan.leaf_ends[slot - 1] = 1;
            } else {
                plan.inner.push_back(i);
            }
        }
        subtree.slot_end = slot;
        subtree.inner_end = static_cast<std::uint32_t>(plan.inner.size());
    }
}

std::uint32_t depth_below(const Tree& tree, std::uint32_t node) {
    const Node& n = tree.nodes[node];
    if (n.is_leaf()) return 1;
    return 1 + std::max(depth_below(tree, node + 1), depth_below(tree, n.index));
}

// The build into `tree` (allocated afresh; its wide layout kept) with `scratch` (reused: a
// rebuild through a TreeBuilder allocates no working memory). With `to` (not empty): over the
// swept boxes from `vertices` to `to`, its boxes fitted to them as refit_swept fits them
// (from the build's own boxes: the corners are read once), its wide layout left to fit_wide.
BuildStats build_into(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                      const BuildConfig& config, Tree& tree, detail::BuildScratch& scratch,
                      std::span<const Vec3> to = {}) {
    const bool swept = !to.empty();
    const Stopwatch stopwatch;
    BuildStats stats;
    if (triangles.empty()) {
        tree = Tree{};
        return stats;
    }
    const auto n = static_cast<std::uint32_t>(triangles.size());
    {
        // A fresh tree, keeping only the wide layout and the counters that key it. Writing
        // into the old tree's storage instead was slower wherever freed memory is kept
        // (keep_freed_memory, as the command and the peer bench run): data set D's rebuilds
        // 3.6-3.8 against 2.4-2.6 ms a frame (records/2026-11-26-wide-traversal.md).
        WideTree wide = std::move(tree.wide);
        const std::uint64_t builds = tree.builds, fits = tree.fits;
        tree = Tree{};
        tree.wide = std::move(wide);
        tree.builds = builds;
        tree.fits = fits;
    }
    detail::BuildInput& input = scratch.input;
    detail::make_build_input(triangles, vertices, swept || config.builder == Builder::Sah, input, to);
    detail::RawTree& raw = scratch.raw;
    raw.nodes.resize(2 * std::size_t{n} - 1);
    raw.used = 1;
    raw.ids.resize(n);
    std::iota(raw.ids.begin(), raw.ids.end(), 0u);
    if (config.builder == Builder::Sah) {
        detail::build_sah(input, config, raw);
    } else {
        detail::build_lbvh(input, config, raw, scratch.lbvh);
    }
    std::uint32_t depth = 0;
    to_preorder(raw, tree.nodes, depth);
    tree.triangle_ids.swap(raw.ids);  // the fresh tree takes them; the next build allocates ids again
    tree.leaf_triangles.resize(n);
    tree.leaf_boxes.resize(n);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, n, 8192), [&](const tbb::blocked_range<std::uint32_t>& r) {
        for (std::uint32_t k = r.begin(); k != r.end(); ++k) {
            tree.leaf_triangles[k] = triangles[tree.triangle_ids[k]];
            if (swept) tree.leaf_boxes[k] = input.boxes[tree.triangle_ids[k]];  // else the refit below
        }
    });
    plan_refit(tree, std::max(config.refit_grain, 1u), tree.refit_plan);
    if (config.surface_patches) build_surface_patches(tree);
    // A tree whose wide layout was in use gets it again at once, fitted by the refit below on
    // the way (a separate fit after every rebuild cost a third of a rebuild).
    const bool wide_in_use = !swept && tree.wide.usable && tree.wide.built_for == tree.builds &&
                             tree.wide.fitted_for != ~std::uint64_t{0};
    ++tree.builds;
    if (wide_in_use) {
        prepare_wide(tree);
        if (tree.wide.usable) tree.wide.fitted_for = 0;  // lets refit write through (refit.cpp)
    }
    const RefitStats fitted = swept ? fit_to_leaf_boxes(tree) : refit(tree, triangles, vertices);
    tree.built_cost = fitted.sah_cost;
    stats.nodes = static_cast<std::uint32_t>(tree.nodes.size());
    stats.leaves = (stats.nodes + 1) / 2;
    stats.depth = depth;
    stats.sah_cost = fitted.sah_cost;
    stats.ms = stopwatch.elapsed_ms();
    return stats;
}

}  // namespace

std::uint32_t tree_depth(const Tree& tree) { return tree.empty() ? 0 : depth_below(tree, 0); }

BuildStats build_tree(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                      const BuildConfig& config, Tree& tree) {
    detail::BuildScratch scratch;
    return build_into(triangles, vertices, config, tree, scratch);
}

BuildStats build_swept_tree(std::span<const TriIndices> triangles, std::span<const Vec3> from,
                            std::span<const Vec3> to, const BuildConfig& config, Tree& tree) {
    detail::BuildScratch scratch;
    return build_into(triangles, from, config, tree, scratch, to);
}

TreeBuilder::TreeBuilder() = default;
TreeBuilder::~TreeBuilder() = default;

BuildStats TreeBuilder::build(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                              const BuildConfig& config, Tree& tree) {
    return build_with(triangles, vertices, {}, config, tree);
}

BuildStats TreeBuilder::build_swept(std::span<const TriIndices> triangles, std::span<const Vec3> from,
                                    std::span<const Vec3> to, const BuildConfig& config, Tree& tree) {
    return build_with(triangles, from, to, config, tree);
}

BuildStats TreeBuilder::build_with(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                                   std::span<const Vec3> to, const BuildConfig& config, Tree& tree) {
    std::unique_ptr<detail::BuildScratch> scratch;
    {
        const std::lock_guard lock(m_mutex);
        if (!m_idle.empty()) {
            scratch = std::move(m_idle.back());
            m_idle.pop_back();
        }
    }
    if (!scratch) scratch = std::make_unique<detail::BuildScratch>();
    const BuildStats stats = build_into(triangles, vertices, config, tree, *scratch, to);
    const std::lock_guard lock(m_mutex);
    m_idle.push_back(std::move(scratch));
    return stats;
}

}  // namespace collidescope::bvh
