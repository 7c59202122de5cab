#pragma once
// Per-object AABB hierarchies over triangles (engine/src/bvh; Mode 1, thesis 3.1 and 4.4.1).
//
// Owns the tree types, the two builders (binned SAH, LBVH), refit, the SAH quality measure
// and the validator's contract. Knows nothing of frames' object pairs, the narrow phase or
// threads beyond TBB inside a call: aabb_culler.cpp puts the pieces together, and the `aabb`
// method (engine/src/methods) adds the narrow phase.
//
// Exactness: every box is closed and built from the input coordinates by min/max only, so a
// node box contains its triangles exactly and a box comparison on doubles is exact.

#include "bvh/wide_tree.hpp"
#include "collidescope/aabb_options.hpp"
#include "collidescope/types.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace collidescope::bvh {

/// A closed axis-aligned box. The empty box has lo = +inf, hi = -inf.
struct Aabb {
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};

    void grow(const Vec3& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = p[k] < lo[k] ? p[k] : lo[k];
            hi[k] = p[k] > hi[k] ? p[k] : hi[k];
        }
    }
    void grow(const Aabb& b) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = b.lo[k] < lo[k] ? b.lo[k] : lo[k];
            hi[k] = b.hi[k] > hi[k] ? b.hi[k] : hi[k];
        }
    }
    /// Half the surface area (the SAH's measure); 0 for an empty or flat-to-a-line box.
    double half_area() const {
        const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        if (!(dx >= 0 && dy >= 0 && dz >= 0)) return 0;
        return dx * dy + dy * dz + dz * dx;
    }
    friend bool operator==(const Aabb&, const Aabb&) = default;
};

/// True when the closed boxes share a point (touching counts). All six comparisons, combined
/// without branches: which axis separates two boxes is unpredictable, and the short-circuit
/// form's mispredictions were most of the traversal's time (perf on data set C).
inline bool overlaps(const Aabb& a, const Aabb& b) {
    return static_cast<bool>((a.lo[0] <= b.hi[0]) & (b.lo[0] <= a.hi[0]) &  //
                             (a.lo[1] <= b.hi[1]) & (b.lo[1] <= a.hi[1]) &  //
                             (a.lo[2] <= b.hi[2]) & (b.lo[2] <= a.hi[2]));
}

/// True when `inner` lies within the closed box `outer`.
inline bool contains(const Aabb& outer, const Aabb& inner) {
    for (int k = 0; k < 3; ++k) {
        if (!(outer.lo[k] <= inner.lo[k] && inner.hi[k] <= outer.hi[k])) return false;
    }
    return true;
}

/// The box of a triangle given by its vertex indices (min/max of its corners, exact).
inline Aabb triangle_box(const TriIndices& tri, std::span<const Vec3> vertices) {
    Aabb box;
    box.grow(vertices[tri[0]]);
    box.grow(vertices[tri[1]]);
    box.grow(vertices[tri[2]]);
    return box;
}

/// The box of triangle `tri` of a mesh.
inline Aabb triangle_box(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                         std::uint32_t tri) {
    return triangle_box(triangles[tri], vertices);
}

/// One node, 56 bytes. Nodes are stored in depth-first preorder: an inner node's left child
/// is the next node, so a subtree occupies a contiguous index range.
struct Node {
    Aabb box;
    /// Inner node: index of the right child. Leaf: first slot in Tree::triangle_ids.
    std::uint32_t index = 0;
    /// Leaf: number of triangles (>= 1). Inner node: 0.
    std::uint32_t count = 0;

    bool is_leaf() const { return count != 0; }
};

/// A contiguous subtree [root, end) of the preorder node array.
struct NodeRange {
    std::uint32_t root = 0;
    std::uint32_t end = 0;
};

/// One parallel unit of refit: the subtree `nodes` (a preorder range), with what refit walks
/// in it without branching on the tree's shape: its triangle slots [slot_begin, slot_end),
/// whose leaves are RefitPlan::leaves from leaf_begin on, and its inner nodes
/// RefitPlan::inner[inner_begin, inner_end).
struct RefitSubtree {
    NodeRange nodes;
    std::uint32_t slot_begin = 0;
    std::uint32_t slot_end = 0;
    std::uint32_t leaf_begin = 0;
    std::uint32_t inner_begin = 0;
    std::uint32_t inner_end = 0;
};

/// How refit splits a tree for threads: the subtrees refit in parallel, then the top nodes
/// above them (in preorder; refit walks them backwards). Built by plan_refit.
struct RefitPlan {
    std::vector<RefitSubtree> subtrees;
    std::vector<std::uint32_t> top;
    LargeVector<std::uint32_t> leaves;    ///< every leaf's node index, in slot (= preorder) order
    LargeVector<std::uint8_t> leaf_ends;  ///< per triangle slot: 1 at the last slot of its leaf
    LargeVector<std::uint32_t> inner;     ///< the subtrees' inner nodes, subtree by subtree, in preorder
};

/// What self-collision culling knows of each node's triangles (bvh/surface_patches.hpp):
/// the boundary loop, from the topology at the build, and the projected orientations, from
/// every refit. Empty unless the tree was built with BuildConfig::surface_patches.
struct SurfacePatches {
    LargeVector<std::uint32_t> loop_begin;     ///< per node: first corner in loop_vertices
    LargeVector<std::uint32_t> loop_size;      ///< per node: corners; 0: not one boundary loop
    LargeVector<std::uint32_t> loop_vertices;  ///< the loops' vertex indices, in order
    LargeVector<std::uint32_t> triangles;      ///< per node: triangles below it
    /// Per node, refreshed by refit: bit 2k set when every triangle below projects with
    /// positive orientation onto the plane that drops axis k, bit 2k + 1 when every one
    /// projects with negative orientation. Zero (nothing known) on a swept tree, whose sides
    /// over an interval are kept apart (ccd/swept_patches.hpp).
    LargeVector<std::uint8_t> sides;

    bool empty() const { return loop_size.empty(); }
};

/// The hierarchy of one object. Empty (no nodes) for an object without triangles.
struct Tree {
    LargeVector<Node> nodes;                 ///< preorder; nodes[0] is the root
    LargeVector<std::uint32_t> triangle_ids;  ///< triangle indices in leaf order
    /// The triangles' vertex indices in leaf order (leaf_triangles[k] ==
    /// triangles[triangle_ids[k]]): a copy, so refit and traversal stream them instead of
    /// gathering through triangle_ids (it halved refit's cache misses).
    LargeVector<TriIndices> leaf_triangles;
    /// Each triangle's box in leaf order, set with the node boxes by every refit: the leaf
    /// tests read them in a row instead of gathering three vertices per triangle per test.
    LargeVector<Aabb> leaf_boxes;
    RefitPlan refit_plan;
    SurfacePatches patches;  ///< self-collision culling's per-node data (may be empty)
    double built_cost = 0;  ///< sah_cost right after the last build (quality reference)
    std::uint64_t builds = 0;  ///< builds of this tree so far (the wide layout's key)
    std::uint64_t fits = 0;    ///< builds and refits so far: changes whenever the boxes do
    WideTree wide;  ///< the 4-wide layout, fitted on demand (wide_tree.hpp); may be stale

    bool empty() const { return nodes.empty(); }
};

/// Which builder builds a tree: Sah (top-down, binned surface area heuristic) or Lbvh (Morton
/// codes sorted, split at the highest differing bit: Karras-style linear BVH). One definition:
/// the public option, AabbBuilder (collidescope/aabb_options.hpp).
using Builder = AabbBuilder;

/// Options of a build.
struct BuildConfig {
    /// LBVH is the default: as the rebuild of a deforming mesh it wins (bench_bvh_build:
    /// several times faster to build; the SAH tree's traversal gain does not pay for it).
    Builder builder = Builder::Lbvh;
    std::uint32_t max_leaf_size = 4;   ///< leaves hold 1 .. max_leaf_size triangles
    std::uint32_t sah_bins = 16;       ///< bins per axis for the SAH builder
    std::uint32_t parallel_grain = 4096;  ///< ranges below this many triangles build serially
    std::uint32_t refit_grain = 2048;  ///< nodes per parallel refit subtree (RefitPlan)
    /// Also build Tree::patches (objects tested for self-collision).
    bool surface_patches = false;
};

/// What a build did.
struct BuildStats {
    double ms = 0;               ///< wall time of the whole build (incl. its final refit)
    std::uint32_t nodes = 0;
    std::uint32_t leaves = 0;
    std::uint32_t depth = 0;     ///< levels (a lone leaf: 1)
    double sah_cost = 0;         ///< sah_cost of the new tree
};

/// Builds `tree` from scratch over every triangle of the mesh, in parallel (TBB). The spans
/// are read during the call only. Deterministic: the same input gives the same tree for any
/// thread count, whatever `tree` held before, apart from its wide layout: one in use is
/// kept and collapsed again within the build (wide_tree.hpp), with the counters that key it.
BuildStats build_tree(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                      const BuildConfig& config, Tree& tree);

/// build_tree over the triangles' swept boxes between two positions of the mesh (each the
/// box of the triangle's corners at `from` and at `to`, which holds it throughout a linear
/// motion between them), for between-frames detection: the tree's boxes come out as
/// refit_swept would fit them, from the build's own boxes (each corner read once, not again
/// by a refit), and its quality reference is theirs. A wide layout goes stale (fit_wide).
BuildStats build_swept_tree(std::span<const TriIndices> triangles, std::span<const Vec3> from,
                            std::span<const Vec3> to, const BuildConfig& config, Tree& tree);

namespace detail {
struct BuildScratch;
}

/// build_tree for a caller that builds again and again (the `aabb` method's rebuilds): it
/// keeps the builds' working memory (per-triangle centroids, Morton keys and their sort
/// buffer, the raw nodes) for the next build instead of freeing it. Memory touched for the first time was most of a
/// build's time on the CI VM (a 22,598-triangle build: 11.3 ms with 668 first-touch page
/// faults, 1.8 ms warm; records/2026-11-26-wide-traversal.md). Thread-safe: builds
/// running at once each take their own working memory.
class TreeBuilder {
public:
    TreeBuilder();
    ~TreeBuilder();
    TreeBuilder(const TreeBuilder&) = delete;
    TreeBuilder& operator=(const TreeBuilder&) = delete;

    /// Same contract and result as build_tree.
    BuildStats build(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                     const BuildConfig& config, Tree& tree);
    /// Same contract and result as build_swept_tree.
    BuildStats build_swept(std::span<const TriIndices> triangles, std::span<const Vec3> from,
                           std::span<const Vec3> to, const BuildConfig& config, Tree& tree);

private:
    BuildStats build_with(std::span<const TriIndices> triangles, std::span<const Vec3> vertices,
                          std::span<const Vec3> to, const BuildConfig& config, Tree& tree);

    std::mutex m_mutex;
    std::vector<std::unique_ptr<detail::BuildScratch>> m_idle;  ///< working memory not in use
};

/// What a refit did.
struct RefitStats {
    double ms = 0;
    std::uint32_t nodes = 0;
    double sah_cost = 0;  ///< of the refit tree
    /// sah_cost / built_cost: 1 right after a build, growing as the tree degrades.
    double quality = 1;
};

/// Recomputes every node box bottom-up from `vertices` (same topology as at the build):
/// leaves from their triangles, inner nodes as the union of their children; the subtrees of
/// the refit plan in parallel, then the top. Deterministic. With patches, their sides too.
RefitStats refit(Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> vertices);

/// Refit for a motion between two frames: each box holds its triangles at `from` and at `to`
/// (so throughout a linear motion between them). The patches' sides are left as they were,
/// and a wide layout goes stale. quality: against the cost of the last build's boxes.
RefitStats refit_swept(Tree& tree, std::span<const TriIndices> triangles, std::span<const Vec3> from,
                       std::span<const Vec3> to);

/// Fits the node boxes to Tree::leaf_boxes as they stand (each leaf the union of its slots'
/// boxes, each inner node of its children's), as refit does after computing them; the
/// patches' sides are left as they were, and a wide layout goes stale. quality: against the
/// last build's cost.
RefitStats fit_to_leaf_boxes(Tree& tree);

/// The SAH cost of a tree: (sum over inner nodes of half_area + sum over leaves of
/// half_area * count) / half_area(root); traversal and triangle costs both 1. A root of zero
/// area (all triangles on one line or point) gives the node count, so it stays comparable.
double sah_cost(const Tree& tree);

/// Levels of the tree (0 for an empty tree).
std::uint32_t tree_depth(const Tree& tree);

}  // namespace collidescope::bvh
