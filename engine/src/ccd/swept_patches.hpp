#pragma once
// Self-collision culling between frames (engine/src/ccd, private): the per-frame proof of
// bvh/surface_patches.hpp (a node's triangles all project with one strict orientation onto a
// coordinate plane, and its boundary loop projects to a simple polygon: then no two of them
// meet outside their shared vertices' hull) made to hold at every time of the interval, with
// every vertex moving linearly from `from` to `to`:
//  1. each triangle's projected signed area is a quadratic in t; its three Bernstein
//     coefficients share one strict sign (beyond a static bound of their rounding), so the
//     area keeps it throughout;
//  2. the boundary loop (from the build, topological) stays simple in projection: every edge
//     keeps positive length, consecutive edges never fold back, and other edges stay apart
//     along some fixed direction at both ends (the gap along a fixed direction between two
//     linearly moving point sets is concave in t, so positive at both ends is positive
//     throughout).
// A node proven so has no pair to test: its whole subtree is skipped by the self walk.
// Conservative throughout: a condition not proven only keeps a node from being skipped.

#include "bvh/bvh.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope::ccd {

/// Bit 2k set when the triangle (a, b, c), each corner moving linearly from its `from` to its
/// `to` position, projects with positive orientation onto the plane dropping axis k at every
/// time of [0, 1]; bit 2k + 1 when with negative orientation throughout.
std::uint8_t swept_triangle_sides(const TriIndices& t, std::span<const Vec3> from, std::span<const Vec3> to);

/// Per node of `tree`, the AND of swept_triangle_sides over the triangles below it.
void swept_node_sides(const bvh::Tree& tree, std::span<const Vec3> from, std::span<const Vec3> to,
                      std::vector<std::uint8_t>& sides);

/// True when the closed polygon through from/to[loop[0]], ..., from/to[loop[n - 1]], projected
/// onto the plane dropping axis `drop`, is proven simple at every time of [0, 1].
bool swept_loop_stays_simple(std::span<const std::uint32_t> loop, std::span<const Vec3> from,
                             std::span<const Vec3> to, int drop);

/// True when the triangles below `node` are proven embedded at every time of the interval:
/// `sides` from swept_node_sides, the loop from tree.patches (which must not be empty).
bool swept_patch_is_embedded(const bvh::Tree& tree, std::span<const std::uint8_t> sides, std::uint32_t node,
                             std::span<const Vec3> from, std::span<const Vec3> to);

}  // namespace collidescope::ccd
