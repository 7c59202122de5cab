// Closed segment and triangle contact tests (see contact_tests.hpp).
//
// Coplanar configurations are decided in a 2D coordinate projection. A projection that drops
// axis k is injective on a plane whenever the plane's normal has a nonzero k component, so
// for a non-degenerate triangle we project where its 2D image is non-degenerate. For two
// segments we do not know such a plane, so we require contact in all three projections:
// contact in 3D implies contact in every projection, and the coplanar points lie in some
// plane on which one of the three projections is injective.

#include "geometry/contact_tests.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>

namespace collidescope::contact {
namespace {

/// x within the closed bounding box of p and q in the two coordinates kept by `drop`.
bool within_box_2d(const Vec3& x, const Vec3& p, const Vec3& q, int drop) {
    for (int k = 0; k < 3; ++k) {
        if (k == drop) continue;
        if (x[k] < std::min(p[k], q[k]) || x[k] > std::max(p[k], q[k])) return false;
    }
    return true;
}

/// x in the closed 2D triangle (a, b, c) whose projection has orientation `o` != 0.
bool point_in_triangle_2d(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c, int o,
                          int drop) {
    return orient2d(a, b, x, drop) * o >= 0 && orient2d(b, c, x, drop) * o >= 0 &&
           orient2d(c, a, x, drop) * o >= 0;
}

/// Coplanar segment and non-degenerate triangle, decided in the projection `drop` where the
/// triangle has orientation `o` != 0: an endpoint inside, or the segment crosses an edge.
bool coplanar_segment_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                               const Vec3& c, int o, int drop) {
    return point_in_triangle_2d(p, a, b, c, o, drop) || point_in_triangle_2d(q, a, b, c, o, drop) ||
           segments_intersect_2d(p, q, a, b, drop) || segments_intersect_2d(p, q, b, c, drop) ||
           segments_intersect_2d(p, q, c, a, drop);
}

}  // namespace

bool segments_intersect_2d(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s,
                           int drop) {
    const int o1 = orient2d(p, q, r, drop), o2 = orient2d(p, q, s, drop);
    const int o3 = orient2d(r, s, p, drop), o4 = orient2d(r, s, q, drop);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // proper crossing
    // Otherwise contact needs an endpoint on the other segment (collinear and within it).
    return (o1 == 0 && within_box_2d(r, p, q, drop)) || (o2 == 0 && within_box_2d(s, p, q, drop)) ||
           (o3 == 0 && within_box_2d(p, r, s, drop)) || (o4 == 0 && within_box_2d(q, r, s, drop));
}

int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
    for (int drop : {2, 1, 0})
        if (orient2d(a, b, c, drop) != 0) return drop;
    return -1;
}

bool point_on_segment(const Vec3& x, const Vec3& p, const Vec3& q) {
    if (!collinear(p, q, x)) return false;
    for (int k = 0; k < 3; ++k)
        if (x[k] < std::min(p[k], q[k]) || x[k] > std::max(p[k], q[k])) return false;
    return true;
}

bool segments_intersect(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    if (orient3d(p, q, r, s) != 0) return false;
    return segments_intersect_2d(p, q, r, s, 0) && segments_intersect_2d(p, q, r, s, 1) &&
           segments_intersect_2d(p, q, r, s, 2);
}

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, int op, int oq, const Vec3& a,
                                 const Vec3& b, const Vec3& c) {
    if (op * oq > 0) return false;  // both ends strictly on one side of the plane
    // A non-zero side needs a non-degenerate triangle: the projection is asked only when both
    // are zero.
    if (op == 0 && oq == 0) {
        const int drop = projection_axis(a, b, c);
        if (drop < 0)  // the triangle is the segment (or point) its edges cover
            return segments_intersect(p, q, a, b) || segments_intersect(p, q, b, c) ||
                   segments_intersect(p, q, c, a);
        return coplanar_segment_triangle(p, q, a, b, c, orient2d(a, b, c, drop), drop);
    }
    // The segment meets the plane in one point (p != q here: equal ends would give op == oq,
    // handled above). The line pq passes through the closed triangle iff it sees the three
    // edges with one orientation (zeros allowed: the line meets an edge or a corner).
    const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                 const Vec3& c) {
    return segment_intersects_triangle(p, q, orient3d(a, b, c, p), orient3d(a, b, c, q), a, b, c);
}

}  // namespace collidescope::contact
