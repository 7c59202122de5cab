#pragma once
/// Closed point-segment-triangle contact tests built on the exact predicates; the pieces the
/// triangle-triangle test and the self-collision rule are made of. All decide exactly, all
/// accept degenerate inputs (a segment with equal ends is a point, a triangle with collinear
/// corners is the segment or point it spans).

#include "collidescope/types.hpp"

namespace collidescope::contact {

/// The coordinate axis whose dropping keeps triangle (a, b, c) non-degenerate in 2D, or -1
/// when the corners are collinear (or coincide).
int projection_axis(const Vec3& a, const Vec3& b, const Vec3& c);

/// True when a, b and c lie on one line (coincident points included).
inline bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
    return projection_axis(a, b, c) < 0;
}

/// True when x lies on the closed segment [p, q] (p == q allowed).
bool point_on_segment(const Vec3& x, const Vec3& p, const Vec3& q);

/// True when the closed segments [p, q] and [r, s], projected onto the coordinate plane that
/// drops axis `drop`, share a point; segments may be points.
bool segments_intersect_2d(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, int drop);

/// True when the closed segments [p, q] and [r, s] share a point.
bool segments_intersect(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);

/// True when the closed segment [p, q] and the closed triangle (a, b, c) share a point.
/// `op`, `oq` are orient3d(a, b, c, p) and orient3d(a, b, c, q), computed by the caller
/// (who often has them already).
bool segment_intersects_triangle(const Vec3& p, const Vec3& q, int op, int oq, const Vec3& a,
                                 const Vec3& b, const Vec3& c);

/// As above, computing the orientations itself.
bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                 const Vec3& c);

}  // namespace collidescope::contact
