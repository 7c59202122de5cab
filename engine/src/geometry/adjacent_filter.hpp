#pragma once
/// Adjacent pairs decided where the traversal finds them (issue 23): two triangles of one
/// object that share a vertex index always have overlapping boxes, so on a mesh every
/// triangle meets about twelve of them a frame, and nearly all are apart under the self rule
/// for a reason one or two orient3d signs certify. adjacent_apart gives that proof with
/// the floating-point filter alone (inline, no predicate counters); what it cannot prove
/// goes to the narrow phase's exact self rule as before. Exact either way: it answers true
/// only when self_triangles_collide would answer false (docs/explanation/algorithms.md, "Adjacent pairs").

#include "collidescope/types.hpp"

#include <cmath>
#include <limits>

namespace collidescope::filter {

/// Shewchuk's o3derrboundA is (7 + 56 eps) eps; 8 eps plus an absolute term that covers
/// gradual underflow in the products (predicates.cpp runs the same filter first).
inline constexpr double kOrient3dBound = 8.0 * (std::numeric_limits<double>::epsilon() / 2);
inline constexpr double kOrient3dAbsoluteBound = 0x1p-960;

/// The sign of orient3d(a, b, c, d) when the filter certifies it (+1 or -1), else 0
/// (undecided: zero, nearly zero, or overflow; the exact predicate must answer).
inline int orient3d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double adx = a.x() - d.x(), bdx = b.x() - d.x(), cdx = c.x() - d.x();
    const double ady = a.y() - d.y(), bdy = b.y() - d.y(), cdy = c.y() - d.y();
    const double adz = a.z() - d.z(), bdz = b.z() - d.z(), cdz = c.z() - d.z();
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
    const double bound = kOrient3dBound * permanent + kOrient3dAbsoluteBound;
    // Comparisons with NaN or infinity (overflow) fail: undecided.
    if (!(permanent < std::numeric_limits<double>::max())) return 0;
    return (det > bound) - (-det > bound);
}

/// True when the triangles `a` and `b` of one object share a vertex index and are proven
/// apart under the self rule (DESIGN.md: they collide iff they meet outside the hull of
/// what they share) by certified signs. False when they share no index, or when the filter
/// cannot decide (the pair is then an ordinary candidate). Each triangle must have three
/// distinct indices, else false. `v` is the object's vertex array.
///  - Shared edge (u, w), apexes p of a and q of b: orient3d(u, w, p, q) != 0 puts the four
///    points in general position, so the two planes meet in line uw, which meets each
///    triangle in its edge [u, w] only: they meet in [u, w], the hull of the shared vertices.
///  - One shared vertex s, a = (s, p1, p2), b = (s, q1, q2): p1 and p2 strictly on one side
///    of b's plane (s, q1, q2 not collinear, since the signs are non-zero) leave a touching
///    that plane at s alone, and b lies in it; or the same with the roles swapped.
inline bool adjacent_apart(const TriIndices& a, const TriIndices& b, const Vec3* v) {
    // Bit i * 3 + j set when a[i] == b[j].
    unsigned match = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) match |= static_cast<unsigned>(a[i] == b[j]) << (i * 3 + j);
    if (match == 0) return false;
    if (a[0] == a[1] || a[1] == a[2] || a[0] == a[2] || b[0] == b[1] || b[1] == b[2] || b[0] == b[2])
        return false;
    const int shared = __builtin_popcount(match);
    if (shared == 1) {
        const int at = __builtin_ctz(match);
        const int i = at / 3, j = at % 3;
        const Vec3& s = v[a[i]];
        const Vec3& p1 = v[a[(i + 1) % 3]];
        const Vec3& p2 = v[a[(i + 2) % 3]];
        const Vec3& q1 = v[b[(j + 1) % 3]];
        const Vec3& q2 = v[b[(j + 2) % 3]];
        const int s1 = orient3d_filtered(s, q1, q2, p1);
        if (s1 != 0 && s1 == orient3d_filtered(s, q1, q2, p2)) return true;
        const int s2 = orient3d_filtered(s, p1, p2, q1);
        return s2 != 0 && s2 == orient3d_filtered(s, p1, p2, q2);
    }
    if (shared == 2) {
        // The corner of each triangle that the other lacks: the row (of a) or column (of b)
        // with no match.
        int i = 0, j = 0;
        while (match & (7u << (i * 3))) ++i;
        while (match & (0x49u << j)) ++j;  // 0x49: bits 0, 3, 6, one column
        const Vec3& u = v[a[(i + 1) % 3]];
        const Vec3& w = v[a[(i + 2) % 3]];
        return orient3d_filtered(u, w, v[a[i]], v[b[j]]) != 0;
    }
    return false;  // three shared indices: the same triangle, left to the exact rule
}

}  // namespace collidescope::filter
