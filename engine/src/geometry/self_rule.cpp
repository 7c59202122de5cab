// The self-collision rule (DESIGN.md): two triangles of one object that share vertex indices
// collide iff their intersection holds a point outside the convex hull H of the shared
// vertices. Derivations (docs/explanation/algorithms.md has them in full):
//
// Shared edge (u, v), u != v in space, T1 = (u, v, a), T2 = (u, v, b), H = [u, v]:
//  - both degenerate: two intervals of line uv that contain [u, v]; they overlap beyond it
//    iff a and b both stick out past the same end;
//  - one degenerate: the segment lies on line uv, which meets the other triangle only in
//    [u, v]: never;
//  - neither: not coplanar, they meet in [u, v] only; coplanar, they fold over iff a and b
//    lie strictly on the same side of line uv.
// Shared vertex v, T1 = (v, a, b), T2 = (v, c, d), H = {v}: T1 ∩ T2 is convex and holds v;
// it holds another point x iff (1) edge [a, b] meets T2 and v is not on [a, b], or the same
// with the roles swapped, or (2) an edge direction a - v, b - v of T1 lies in the tangent
// cone of T2 at v, or c - v, d - v in that of T1. (The far end of [v, x] lies on an edge of
// T1 or T2: on the opposite edge it is case 1, on an edge through v the edge's direction is
// in both cones; in the coplanar case the cone T1 ∩ T2 near v is bounded by such a
// direction.) A shared edge whose ends coincide in space reduces to the shared-vertex case.

#include "collidescope/geometry.hpp"
#include "geometry/contact_tests.hpp"

#include <algorithm>

namespace collidescope {
namespace {

using contact::collinear;
using contact::point_on_segment;
using contact::projection_axis;
using contact::segment_intersects_triangle;

bool contains(const TriIndices& t, std::uint32_t index) {
    return std::find(t.begin(), t.end(), index) != t.end();
}

bool subset_of(const TriIndices& t, const TriIndices& of) {
    return contains(of, t[0]) && contains(of, t[1]) && contains(of, t[2]);
}

/// Exact componentwise sign equality of x - v and y - v (same ray from v when collinear).
bool same_direction(const Vec3& v, const Vec3& x, const Vec3& y) {
    for (int k = 0; k < 3; ++k) {
        const int sx = (x[k] > v[k]) - (x[k] < v[k]);
        const int sy = (y[k] > v[k]) - (y[k] < v[k]);
        if (sx != sy) return false;
    }
    return true;
}

/// True when q != v and the direction q - v lies in the tangent cone at v of the closed
/// triangle (v, c, d), i.e. the segment from v towards q enters the triangle.
bool direction_in_cone(const Vec3& v, const Vec3& q, const Vec3& c, const Vec3& d) {
    if (q == v) return false;
    const int drop = projection_axis(v, c, d);
    if (drop < 0) {  // a segment through v (or a point): the rays towards c and d
        return (c != v && collinear(v, c, q) && same_direction(v, q, c)) ||
               (d != v && collinear(v, d, q) && same_direction(v, q, d));
    }
    if (orient3d(v, c, d, q) != 0) return false;
    const int o = orient2d(v, c, d, drop);
    return orient2d(v, c, q, drop) * o >= 0 && orient2d(v, q, d, drop) * o >= 0;
}

/// Corners of `t` other than one occurrence of `shared`, in index order.
std::array<std::uint32_t, 2> others(const TriIndices& t, std::uint32_t shared) {
    const int at = t[0] == shared ? 0 : (t[1] == shared ? 1 : 2);
    return {t[(at + 1) % 3], t[(at + 2) % 3]};
}

/// Coplanar shared-vertex case, both triangles non-degenerate: T1 = (v, a, b) and
/// T2 = (v, c, d) in one plane, on which the projection dropping `drop` is injective, with
/// 2D orientations o1, o2 != 0. Each triangle lies in its cone at v and contains every
/// direction of that cone near v, so T1 ∩ T2 holds a point other than v iff the two cones
/// share a direction; two closed circular arcs shorter than a half-turn meet iff an end of
/// one lies in the other, so it suffices to test a, b in T2's cone and c, d in T1's. This is
/// rule (2) of the header with one projection and four shared orient2d signs.
bool coplanar_cones_overlap(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c,
                            const Vec3& d, int o1, int o2, int drop) {
    const int ac = orient2d(v, a, c, drop), ad = orient2d(v, a, d, drop);
    const int bc = orient2d(v, b, c, drop), bd = orient2d(v, b, d, drop);
    const bool a_in_t2 = -ac * o2 >= 0 && ad * o2 >= 0;  // orient2d(v, c, a) = -ac
    const bool b_in_t2 = -bc * o2 >= 0 && bd * o2 >= 0;
    const bool c_in_t1 = ac * o1 >= 0 && -bc * o1 >= 0;  // orient2d(v, c, b) = -bc
    const bool d_in_t1 = ad * o1 >= 0 && -bd * o1 >= 0;
    return a_in_t2 || b_in_t2 || c_in_t1 || d_in_t1;
}

/// Shared-vertex case with T1 = (v, a, b), T2 = (v, c, d).
bool shared_vertex_collide(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c,
                           const Vec3& d) {
    // a and b strictly on one side of T2's plane: T1 touches that plane only at v.
    const int sa = orient3d(v, c, d, a), sb = orient3d(v, c, d, b);
    if (sa * sb > 0) return false;
    const int sc = orient3d(v, a, b, c), sd = orient3d(v, a, b, d);
    if (sc * sd > 0) return false;
    if (sa == 0 && sb == 0 && sc == 0 && sd == 0) {  // coplanar (flat cloth): cones decide
        const int drop = projection_axis(v, c, d);
        if (drop >= 0) {
            // a and b lie in T2's plane (sa = sb = 0), where this projection is injective,
            // so o1 != 0 exactly when T1 is non-degenerate.
            const int o1 = orient2d(v, a, b, drop);
            if (o1 != 0) return coplanar_cones_overlap(v, a, b, c, d, o1, orient2d(v, c, d, drop), drop);
        }
    }
    if (!point_on_segment(v, a, b) && segment_intersects_triangle(a, b, sa, sb, v, c, d))
        return true;
    if (!point_on_segment(v, c, d) && segment_intersects_triangle(c, d, sc, sd, v, a, b))
        return true;
    return direction_in_cone(v, a, c, d) || direction_in_cone(v, b, c, d) ||
           direction_in_cone(v, c, a, b) || direction_in_cone(v, d, a, b);
}

/// Shared-edge case with T1 = (u, v, a), T2 = (u, v, b), u != v in space.
bool shared_edge_collide(const Vec3& u, const Vec3& v, const Vec3& a, const Vec3& b) {
    const bool flat_a = collinear(u, v, a), flat_b = collinear(u, v, b);
    if (flat_a && flat_b) {
        int k = 0;  // an axis along which u and v differ orders the line
        while (u[k] == v[k]) ++k;
        const bool up = v[k] > u[k];
        const auto beyond_u = [&](const Vec3& x) { return up ? x[k] < u[k] : x[k] > u[k]; };
        const auto beyond_v = [&](const Vec3& x) { return up ? x[k] > v[k] : x[k] < v[k]; };
        return (beyond_u(a) && beyond_u(b)) || (beyond_v(a) && beyond_v(b));
    }
    if (flat_a || flat_b) return false;
    if (orient3d(u, v, a, b) != 0) return false;
    const int drop = projection_axis(u, v, a);
    return orient2d(u, v, a, drop) * orient2d(u, v, b, drop) > 0;
}

}  // namespace

bool self_triangles_collide(const TriIndices& ia, const std::array<Vec3, 3>& pa,
                            const TriIndices& ib, const std::array<Vec3, 3>& pb) {
    // One triangle spanned by shared vertices lies inside H: the intersection cannot leave it.
    if (subset_of(ia, ib) || subset_of(ib, ia)) return false;
    std::array<std::uint32_t, 3> shared{};
    int shared_count = 0;
    for (std::uint32_t index : ia)
        if (contains(ib, index) &&
            std::find(shared.begin(), shared.begin() + shared_count, index) ==
                shared.begin() + shared_count)
            shared[shared_count++] = index;
    if (shared_count == 0) return triangles_intersect(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);

    const auto corner = [](const TriIndices& t, const std::array<Vec3, 3>& p,
                           std::uint32_t index) -> const Vec3& {
        return p[t[0] == index ? 0 : (t[1] == index ? 1 : 2)];
    };
    if (shared_count == 2) {
        // Neither triangle is a subset, so each has three distinct indices.
        const std::uint32_t iu = shared[0], iv = shared[1];
        const Vec3& u = corner(ia, pa, iu);
        const Vec3& v = corner(ia, pa, iv);
        const auto apex = [&](const TriIndices& t, const std::array<Vec3, 3>& p) -> const Vec3& {
            for (int k = 0; k < 3; ++k)
                if (t[k] != iu && t[k] != iv) return p[k];
            return p[0];  // unreachable: three distinct indices, two shared
        };
        const Vec3& a = apex(ia, pa);
        const Vec3& b = apex(ib, pb);
        if (u != v) return shared_edge_collide(u, v, a, b);
        return shared_vertex_collide(u, u, a, u, b);  // H is the point u == v
    }
    const std::uint32_t iv = shared[0];
    const auto oa = others(ia, iv);
    const auto ob = others(ib, iv);
    return shared_vertex_collide(corner(ia, pa, iv), corner(ia, pa, oa[0]), corner(ia, pa, oa[1]),
                                 corner(ib, pb, ob[0]), corner(ib, pb, ob[1]));
}

}  // namespace collidescope
