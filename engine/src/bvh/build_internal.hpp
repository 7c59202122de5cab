#pragma once
// What the two builders share (engine/src/bvh, private): the per-triangle input and the raw
// tree they produce, which build.cpp turns into the preorder Tree.

#include "bvh/bvh.hpp"
#include "bvh/radix_sort.hpp"

#include <atomic>
#include <span>
#include <vector>

namespace collidescope::bvh::detail {

/// Per-triangle boxes and centroids, computed once per build in parallel.
struct BuildInput {
    LargeVector<Aabb> boxes;  ///< empty unless asked for (make_build_input)
    LargeVector<std::array<double, 3>> centroids;  ///< box centres (only steer the splits)
    Aabb centroid_bounds;
};

/// A node of the raw tree: inner nodes have their children at `first` and `first + 1`.
struct RawNode {
    std::uint32_t first = 0;  ///< inner: left child; leaf: first slot in the id array
    std::uint32_t count = 0;  ///< leaf: triangles; inner: 0
};

/// The builders' output: nodes allocated in pairs by an atomic counter (so their order may
/// depend on thread timing; the structure does not), the root at 0, and the triangle ids
/// permuted so that every leaf is a contiguous range.
struct RawTree {
    LargeVector<RawNode> nodes;
    std::atomic<std::uint32_t> used{1};
    LargeVector<std::uint32_t> ids;

    /// Allocates two sibling nodes; returns the first's index.
    std::uint32_t allocate_pair() { return used.fetch_add(2, std::memory_order_relaxed); }
};

/// The LBVH builder's keys and its radix sort's second buffer.
struct LbvhScratch {
    LargeVector<MortonKey> keys;
    LargeVector<MortonKey> sorted;
};

/// Everything a build writes besides the tree (bvh.hpp's TreeBuilder keeps it between builds).
struct BuildScratch {
    BuildInput input;
    RawTree raw;
    LbvhScratch lbvh;
};

/// Fills `input` with the triangles' centroids and their bounds, and their boxes too when
/// `with_boxes` (the SAH builder bins them; the LBVH builder needs centroids only). Reuses
/// `input`'s storage. With `to` (not empty), each triangle's box is its swept box: the box
/// of its corners at `vertices` and at `to`.
void make_build_input(std::span<const TriIndices> triangles, std::span<const Vec3> vertices, bool with_boxes,
                      BuildInput& input, std::span<const Vec3> to = {});

/// Top-down binned SAH build into `raw` (nodes sized 2n - 1, ids 0..n-1 on entry).
void build_sah(const BuildInput& input, const BuildConfig& config, RawTree& raw);

/// Linear (Morton code) build into `raw` (same contract as build_sah), its keys in `scratch`.
void build_lbvh(const BuildInput& input, const BuildConfig& config, RawTree& raw, LbvhScratch& scratch);

/// Maps a value in [lo, lo + 1/scale) to 0 .. cells - 1, clamping anything else (including
/// NaN, from infinite or tiny extents) into range. Used for bins and Morton cells.
inline std::uint32_t cell_of(double value, double lo, double scale, std::uint32_t cells) {
    const double t = (value - lo) * scale;
    if (!(t >= 0)) return 0;
    if (t >= static_cast<double>(cells)) return cells - 1;
    return static_cast<std::uint32_t>(t);
}

}  // namespace collidescope::bvh::detail
