#pragma once
/// Exact geometric predicates and the triangle-triangle test (engine/src/geometry).
///
/// Every function here decides exactly on its double inputs: a floating-point filter with a
/// static error bound answers most calls, cheap exact arguments (a repeated point; a
/// determinant whose every operation is exact in doubles) most of the rest, and an exact
/// fallback (expansion arithmetic, with GMP rationals where expansions could underflow or
/// overflow) what is left. No epsilon.
/// All functions are pure and thread-safe.

#include "collidescope/types.hpp"

#include <cstdint>

namespace collidescope {

/// Sign of the orientation determinant of (a, b, c, d): +1 when d lies below the plane of
/// (a, b, c) seen with a, b, c counter-clockwise (Shewchuk's convention), -1 above, 0 coplanar.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of the 2D orientation of (a, b, c) projected onto the coordinate plane that drops
/// axis `drop` (0 = x, 1 = y, 2 = z): +1 counter-clockwise, -1 clockwise, 0 collinear.
int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int drop);

/// True when the closed triangles (a0, a1, a2) and (b0, b1, b2) share at least one point:
/// crossing, touching at a point, edge contact and coplanar overlap all count. Degenerate
/// triangles are the segment or point they are.
bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                         const Vec3& b0, const Vec3& b1, const Vec3& b2);

/// triangles_intersect for two triangles whose six corners are known to lie exactly in one
/// plane: the same answer, without the six plane-side orientations (each zero, and each costly
/// to prove zero in exact arithmetic).
bool coplanar_triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                  const Vec3& b0, const Vec3& b1, const Vec3& b2);

/// Self-collision rule for two triangles of one object (DESIGN.md): when they share vertex
/// indices they collide only if their intersection holds a point outside the convex hull of
/// the shared vertices; identical index sets never collide; with no shared index this is
/// triangles_intersect. `ia`/`ib` are the triangles' vertex indices, `pa`/`pb` their corners.
bool self_triangles_collide(const TriIndices& ia, const std::array<Vec3, 3>& pa,
                            const TriIndices& ib, const std::array<Vec3, 3>& pb);

/// Counters of the predicates' stages, per calling thread. The narrow phase reads the
/// difference around its work to report how many predicate calls needed the exact fallback.
struct PredicateCounters {
    std::uint64_t filtered = 0;  ///< predicate calls decided by the floating-point filter
    std::uint64_t shortcut = 0;  ///< calls the filter left open, decided exactly without
                                 ///< expansions (a repeated point; an exact double evaluation)
    std::uint64_t exact = 0;     ///< calls that needed the exact fallback (expansions or GMP)
};

/// The calling thread's counters (monotonic; never reset by the library).
PredicateCounters predicate_counters();

}  // namespace collidescope
