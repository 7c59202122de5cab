#pragma once
/// Is a closed polygon simple in a coordinate projection? The contour test of self-collision
/// culling (bvh/surface_patches.hpp): a patch whose normals all point one way along an axis
/// and whose boundary loop projects to a simple polygon is embedded (docs/explanation/algorithms.md).
/// Exact: orient2d and coordinate comparisons only.

#include "collidescope/types.hpp"

#include <cstdint>
#include <span>

namespace collidescope::contact {

/// True when the closed polygon vertices[loop[0]], vertices[loop[1]], ..., vertices[loop[n-1]],
/// back to the first, projected onto the coordinate plane that drops axis `drop`, is simple:
/// every edge has positive length, consecutive edges meet only at their shared corner and
/// other edges share no point (touching counts). False for fewer than three corners.
/// Expected O(n) (a uniform grid over the edges' boxes) for loops of even-sized edges.
bool projected_loop_is_simple(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices,
                              int drop);

/// The same answer by testing every pair of edges: the slow, obvious reference.
bool projected_loop_is_simple_reference(std::span<const std::uint32_t> loop,
                                        std::span<const Vec3> vertices, int drop);

}  // namespace collidescope::contact
