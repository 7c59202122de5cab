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
// separates them (the 2D separating axis), or a corner of one inside the other, which they
// then share, before the six edge tests.

#include "collidescope/geometry.hpp"
#include "geometry/contact_tests.hpp"

namespace collidescope {
namespace {

bool strictly_one_side(const int s[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

/// What the orientations of coplanar triangles decide before their edges are tested.
enum class InPlane { Separated, Contained, Undecided };

/// A corner of `b` against the lines of a's edges, where `oa` (not 0) is a's orientation in
/// the projection dropping `drop`: Separated when one edge's line has all of b strictly on its
/// outer side (a lies in the closed inner half-plane of each of its edges, so that line parts
/// them); Contained when a corner of b lies on the closed inner side of all three lines (in the
/// closed triangle a: they share that point); else Undecided. The nine signs are taken one
/// line at a time, so a separating first line costs three.
InPlane corners_against_lines(const Vec3& a0, const Vec3& a1, const Vec3& a2, int oa, const Vec3& b0, const Vec3& b1,
                              const Vec3& b2, int drop) {
    const Vec3* a[3] = {&a0, &a1, &a2};
    bool inside[3] = {true, true, true};
    for (int i = 0; i < 3; ++i) {
        const Vec3 &p = *a[i], &q = *a[(i + 1) % 3];
        const int s0 = orient2d(p, q, b0, drop) * oa, s1 = orient2d(p, q, b1, drop) * oa, s2 = orient2d(p, q, b2, drop) * oa;
        if (s0 < 0 && s1 < 0 && s2 < 0) return InPlane::Separated;
        inside[0] = inside[0] && s0 >= 0;
        inside[1] = inside[1] && s1 >= 0;
        inside[2] = inside[2] && s2 >= 0;
    }
    return inside[0] || inside[1] || inside[2] ? InPlane::Contained : InPlane::Undecided;
}

/// Coplanar triangles, A non-degenerate in the projection dropping `drop` (so that projection
/// is one-to-one on their plane), `oa` its orientation there: the lines of A's edges against
/// B's corners, then (for a B non-degenerate in that projection) the lines of B's edges
/// against A's. Undecided pairs (disjoint, overlapping with no corner of one in the other, or
/// B degenerate there with no corner in A) go to the edge tests.
/// The containment answer spares those tests most overlapping pairs (sheets sliding on each
/// other), which the separating lines alone left to them.
InPlane decide_in_plane(const Vec3& a0, const Vec3& a1, const Vec3& a2, int oa, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2, int drop) {
    const InPlane by_a = corners_against_lines(a0, a1, a2, oa, b0, b1, b2, drop);
    if (by_a != InPlane::Undecided) return by_a;
    const int ob = orient2d(b0, b1, b2, drop);
    if (ob == 0) return InPlane::Undecided;
    return corners_against_lines(b0, b1, b2, ob, a0, a1, a2, drop);
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
    // Coplanar, or a degenerate triangle: every side is zero. A's projection axis: the first
    // of z, y, x along which it projects to a non-degenerate triangle (contact::projection_axis).
    for (const int drop : {2, 1, 0}) {
        const int oa = orient2d(a0, a1, a2, drop);
        if (oa == 0) continue;
        const InPlane decided = decide_in_plane(a0, a1, a2, oa, b0, b1, b2, drop);
        if (decided != InPlane::Undecided) return decided == InPlane::Contained;
        break;
    }
    constexpr int zero[3] = {0, 0, 0};
    return edges_meet(a0, a1, a2, zero, b0, b1, b2, zero);
}

}  // namespace collidescope
