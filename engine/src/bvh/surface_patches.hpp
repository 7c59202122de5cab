#pragma once
// Self-collision culling for surfaces (engine/src/bvh): a node of an object's tree whose
// triangles are proven embedded in space has no colliding pair under the self rule, so the
// self-traversal skips its whole subtree (Volino and Magnenat-Thalmann 1994: the normal-cone
// test with its contour condition, made exact; docs/explanation/algorithms.md, "Self-collision culling").
//
// A node's triangles P are proven embedded when, for some axis k:
//  1. every triangle of P projects with one strict orientation onto the plane dropping k
//     (orient2d signs certified by its filter, kept per node by refit in SurfacePatches::sides);
//  2. the boundary chain of P (the sum of its triangles' oriented edges by vertex index, at
//     the build) is one closed loop through distinct vertices;
//  3. that loop projects to a simple polygon (geometry/simple_loop.hpp).
// Then the projection is one-to-one on P: the number of triangles covering a point is the
// winding number of the boundary loop around it, at most 1 for a simple polygon, and the
// case analysis in docs/explanation/algorithms.md rules out contact on edges and corners. So no two
// triangles of P meet outside their shared vertices' hull, and no two vertices coincide.

#include "bvh/bvh.hpp"
#include "geometry/orient2d_filter.hpp"

#include <cstdint>
#include <span>

namespace collidescope::bvh {

/// Fills tree.patches for the tree's current layout: loops and triangle counts from the
/// topology (leaf_triangles); sides sized and cleared (refit sets them). A node whose
/// boundary is not one loop, or is too long to be worth testing (more than 16 + 8 sqrt(t)
/// edges for t triangles), gets no loop, and neither do its ancestors then.
void build_surface_patches(Tree& tree);

/// True when the triangles form a surface worth patches: at least one edge shared by two
/// triangles per two triangles (a grid sheet has about three per two; a closed mesh three; a
/// triangle soup, such as data set E's fragments, none, and patches would only cost).
/// O(n log n); callers keep the answer per topology.
bool surface_like(std::span<const TriIndices> triangles);

/// SurfacePatches::sides bits of the triangle (a, b, c): the projected orientations that
/// orient2d's floating-point filter certifies. An orientation the filter leaves open (zero,
/// or nearly: the triangle is edge-on or nearly so to that axis) sets no bit, which can only
/// keep a node from being culled. A flat cloth's exact zeros would otherwise cost two exact
/// evaluations per triangle per frame.
inline std::uint8_t triangle_sides(const Vec3& a, const Vec3& b, const Vec3& c) {
    std::uint8_t bits = 0;
    for (int k = 0; k < 3; ++k) {
        const int sign = filter::orient2d_filtered(a, b, c, k);
        if (sign > 0) bits |= static_cast<std::uint8_t>(1u << (2 * k));
        if (sign < 0) bits |= static_cast<std::uint8_t>(2u << (2 * k));
    }
    return bits;
}

/// True when the triangles below `node` are proven embedded for `vertices` (the positions
/// the tree was last fitted to): conditions 1 to 3 above. Requires non-empty patches.
bool patch_is_embedded(const Tree& tree, std::uint32_t node, std::span<const Vec3> vertices);

}  // namespace collidescope::bvh
