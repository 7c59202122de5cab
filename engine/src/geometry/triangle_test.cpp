// The exact closed triangle-triangle test (DESIGN.md, "What collide means").
//
// Two closed triangles share a point iff an edge of one meets the other. Non-coplanar: the
// intersection is a segment of T1 ∩ plane(T2) clipped by T2, and each of its ends lies on
// the boundary of T1 or of T2, i.e. on an edge. Coplanar: two convex polygons meet iff
// their boundaries cross or one contains the other, whose edges then lie inside. A
// degenerate triangle is covered by its edges, so the same statement holds for segments and
// points. A plane-side rejection first skips most separated pairs with four orientation
// signs reused by the edge tests; coplanar pairs (flat cloth, sheets lying on each other)
// first look for an edge whose line has the other triangle strictly outside, which
// separates them (the 2D separating axis), before the six edge tests.

#include "collidescope/geometry.hpp"
#include "geometry/contact_tests.hpp"

namespace collidescope {
namespace {

bool strictly_one_side(const int s[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

/// Some corner of (b0, b1, b2) on the inner (closed) side of the line through p, q, where
/// `inner` is the orientation of (p, q, the triangle's third corner).
bool reaches_edge_line(const Vec3& p, const Vec3& q, int inner, const Vec3& b0, const Vec3& b1, const Vec3& b2,
                       int drop) {
    return orient2d(p, q, b0, drop) * inner >= 0 || orient2d(p, q, b1, drop) * inner >= 0 ||
           orient2d(p, q, b2, drop) * inner >= 0;
}

/// Coplanar triangles, A non-degenerate in the projection dropping `drop` (so that projection
/// is one-to-one on their plane): true when the line of an edge of A, or of a non-degenerate
/// B, has the other triangle strictly on its outer side. A triangle lies in the closed inner
/// half-plane of each of its edges, so such a line separates them; when none exists they may
/// still be disjoint, and the edge tests decide.
bool separated_in_plane(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2, int drop) {
    const int oa = orient2d(a0, a1, a2, drop);
    if (!reaches_edge_line(a0, a1, oa, b0, b1, b2, drop) || !reaches_edge_line(a1, a2, oa, b0, b1, b2, drop) ||
        !reaches_edge_line(a2, a0, oa, b0, b1, b2, drop)) {
        return true;
    }
    const int ob = orient2d(b0, b1, b2, drop);
    if (ob == 0) return false;
    return !reaches_edge_line(b0, b1, ob, a0, a1, a2, drop) || !reaches_edge_line(b1, b2, ob, a0, a1, a2, drop) ||
           !reaches_edge_line(b2, b0, ob, a0, a1, a2, drop);
}

bool all_zero(const int s[3]) { return s[0] == 0 && s[1] == 0 && s[2] == 0; }

/// Whether an edge of one triangle meets the other, given each corner's side of the other's
/// plane.
bool edges_meet(const Vec3& a0, const Vec3& a1, const Vec3& a2, const int side_a[3], const Vec3& b0, const Vec3& b1,
                const Vec3& b2, const int side_b[3]) {
    using contact::segment_intersects_triangle;
    return segment_intersects_triangle(a0, a1, side_a[0], side_a[1], b0, b1, b2) ||
           segment_intersects_triangle(a1, a2, side_a[1], side_a[2], b0, b1, b2) ||
           segment_intersects_triangle(a2, a0, side_a[2], side_a[0], b0, b1, b2) ||
           segment_intersects_triangle(b0, b1, side_b[0], side_b[1], a0, a1, a2) ||
           segment_intersects_triangle(b1, b2, side_b[1], side_b[2], a0, a1, a2) ||
           segment_intersects_triangle(b2, b0, side_b[2], side_b[0], a0, a1, a2);
}

}  // namespace

bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                         const Vec3& b0, const Vec3& b1, const Vec3& b2) {
    // Sides of A's corners relative to B's plane, and of B's corners relative to A's plane
    // (all zero for a degenerate triangle, which never rejects).
    const int side_a[3] = {orient3d(b0, b1, b2, a0), orient3d(b0, b1, b2, a1),
                           orient3d(b0, b1, b2, a2)};
    if (strictly_one_side(side_a)) return false;
    const int side_b[3] = {orient3d(a0, a1, a2, b0), orient3d(a0, a1, a2, b1),
                           orient3d(a0, a1, a2, b2)};
    if (strictly_one_side(side_b)) return false;

    if (all_zero(side_a) && all_zero(side_b)) return coplanar_triangles_intersect(a0, a1, a2, b0, b1, b2);
    return edges_meet(a0, a1, a2, side_a, b0, b1, b2, side_b);
}

bool coplanar_triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                  const Vec3& b0, const Vec3& b1, const Vec3& b2) {
    // Coplanar, or a degenerate triangle: every side is zero.
    const int drop = contact::projection_axis(a0, a1, a2);
    if (drop >= 0 && separated_in_plane(a0, a1, a2, b0, b1, b2, drop)) return false;
    constexpr int zero[3] = {0, 0, 0};
    return edges_meet(a0, a1, a2, zero, b0, b1, b2, zero);
}

}  // namespace collidescope
