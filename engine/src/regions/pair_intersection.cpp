// The intersection of two colliding triangles. The signs that decide its shape (which
// vertices lie on which side of the other triangle's plane, and whether the two are coplanar)
// come from the exact orient3d; the points are then constructed in double: where an edge
// crosses the other plane, by its two vertices' distances to it; along the line both planes
// share, the overlap of the two triangles' spans. Coplanar triangles: the first clipped by the
// second in the plane they share (Sutherland-Hodgman), in the projection that drops the axis
// of the larger normal component.

#include "pair_intersection.hpp"

#include "edge_crossing.hpp"

#include "geometry/adjacent_filter.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace collidescope::regions {
namespace {

using Triangle = std::array<Vec3, 3>;
using Kind = PairIntersection::Kind;

// orient3d with its floating-point filter inline, the exact predicate only where the filter
// cannot decide: a pair takes some 18 orientations, nearly all decided by the filter, and the
// calls were a fifth of the demo's regions without the penetration measure (perf, bench_regions).
inline int orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    if (const int sign = filter::orient3d_filtered(a, b, c, d)) return sign;
    return orient3d(a, b, c, d);
}

// One end candidate: a point on the line both planes share, the features it lies on, and
// whether it lies in the other (closed) triangle, decided exactly.
struct End {
    Vec3 point;
    EndKey key;
    bool inside = false;
};

struct Located {
    Feature feature;
    bool inside = false;  ///< in the closed triangle: the signs are not mixed
};

EndKey make_key(Feature x, Feature y) {
    if (y < x) std::swap(x, y);
    return {x, y, true};
}

// The feature of triangle `face` (corners `c`, vertex ids `ids`, triangle `tri` of `object`)
// that a point lies on, from the three signs of the point against its edges (edge m from
// corner m to corner m + 1; 0: on that edge's line): the face, an edge or a vertex.
Located locate(const std::array<int, 3>& on_edge, const TriIndices& ids, std::uint32_t object, std::uint32_t tri) {
    const bool positive = on_edge[0] > 0 || on_edge[1] > 0 || on_edge[2] > 0;
    const bool negative = on_edge[0] < 0 || on_edge[1] < 0 || on_edge[2] < 0;
    const bool inside = !(positive && negative);
    const int zeros = (on_edge[0] == 0) + (on_edge[1] == 0) + (on_edge[2] == 0);
    if (zeros == 1) {
        const int m = on_edge[0] == 0 ? 0 : on_edge[1] == 0 ? 1 : 2;
        const std::uint32_t u = ids[m], v = ids[(m + 1) % 3];
        return {{object, Feature::Edge, std::min(u, v), std::max(u, v)}, inside};
    }
    if (zeros == 2) {  // on two edges' lines: their shared corner
        // Edges 0 (c0 c1), 1 (c1 c2) and 2 (c2 c0): the two zero ones share this corner.
        const int corner = on_edge[0] != 0 ? 2 : on_edge[1] != 0 ? 0 : 1;
        return {{object, Feature::Vertex, ids[corner], ids[corner]}, inside};
    }
    return {{object, Feature::Face, tri, 0}, inside};  // inside, or a flat face (every sign 0)
}

// Which feature of `face` the edge (p, q) crosses it at: signs of (p, q) against each edge.
Located crossed_feature(const Vec3& p, const Vec3& q, const Triangle& face, const TriIndices& ids, std::uint32_t object,
                        std::uint32_t tri) {
    return locate({orient(p, q, face[0], face[1]), orient(p, q, face[1], face[2]), orient(p, q, face[2], face[0])},
                  ids, object, tri);
}

// Which feature of `face` a point in its plane lies on, in the projection that drops the
// axis of the face's largest normal component.
Located point_feature(const Vec3& point, const Triangle& face, const TriIndices& ids, std::uint32_t object,
                      std::uint32_t tri) {
    int drop = 0;
    (face[1] - face[0]).cross(face[2] - face[0]).cwiseAbs().maxCoeff(&drop);
    return locate({orient2d(face[0], face[1], point, drop), orient2d(face[1], face[2], point, drop),
                   orient2d(face[2], face[0], point, drop)},
                  ids, object, tri);
}

// One side of a pair: triangle `t` (vertex ids `ids`, of `object`) against the plane of
// `other` (ids `other_ids`, triangle `other_tri` of `other_object`).
struct Side {
    const Triangle& t;
    const TriIndices& ids;
    std::uint32_t object;
    const Triangle& other;
    const TriIndices& other_ids;
    std::uint32_t other_object;
    std::uint32_t other_tri;
};

// Where side.t meets the plane of side.other: one or two points, with `sides` the exact signs
// of t's vertices against that plane (not all zero).
int plane_crossings(const Side& side, const std::array<int, 3>& sides, std::array<End, 3>& out) {
    const Triangle& t = side.t;
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        if (sides[i] != 0) continue;
        const Located there = point_feature(t[i], side.other, side.other_ids, side.other_object, side.other_tri);
        out[count++] = {t[i], make_key({side.object, Feature::Vertex, side.ids[i], side.ids[i]}, there.feature),
                        there.inside};
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (sides[i] * sides[j] >= 0) continue;  // no strict crossing of this edge
        const double s = crossing_parameter(t[i], t[j], side.other);
        const Feature edge{side.object, Feature::Edge, std::min(side.ids[i], side.ids[j]), std::max(side.ids[i], side.ids[j])};
        const Located there = crossed_feature(t[i], t[j], side.other, side.other_ids, side.other_object, side.other_tri);
        out[count++] = {t[i] + s * (t[j] - t[i]), make_key(edge, there.feature), there.inside};
    }
    return count;
}

// The span of `ends` (1 or 2) along `direction`: the lower and upper end.
std::pair<End, End> span(const std::array<End, 3>& ends, int count, const Vec3& direction) {
    if (count == 1) return {ends[0], ends[0]};
    return direction.dot(ends[0].point) <= direction.dot(ends[1].point) ? std::pair{ends[0], ends[1]}
                                                                         : std::pair{ends[1], ends[0]};
}

Piece crossing(const Triangle& a, const TriIndices& ia, const Triangle& b, const TriIndices& ib,
               const TrianglePair& pair, const std::array<int, 3>& sa, const std::array<int, 3>& sb,
               std::vector<Vec3>* polygon) {
    std::array<End, 3> on_a{}, on_b{};
    const int na = plane_crossings({a, ia, pair.obj_a, b, ib, pair.obj_b, pair.tri_b}, sa, on_a);
    const int nb = plane_crossings({b, ib, pair.obj_b, a, ia, pair.obj_a, pair.tri_a}, sb, on_b);
    if (na == 0 || nb == 0) {  // not a colliding pair after all (a caller's mistake): a corner
        Piece piece;
        piece.ends = {a[0], a[0]};
        if (polygon) polygon->assign(1, a[0]);
        return piece;
    }
    Vec3 direction = (a[1] - a[0]).cross(a[2] - a[0]).cross((b[1] - b[0]).cross(b[2] - b[0]));
    if (!(direction.squaredNorm() > 0)) direction = na == 2 ? on_a[1].point - on_a[0].point : Vec3(1, 0, 0);
    // The segment's ends are the span ends that lie in the other triangle (exactly decided):
    // normally two, one where they touch at a point; one key where several coincide.
    std::array<End, 6> ends{};
    int count = 0;
    for (int i = 0; i < na + nb; ++i) {
        const End& end = i < na ? on_a[i] : on_b[i - na];
        if (!end.inside) continue;
        bool seen = false;
        for (int k = 0; k < count; ++k) seen = seen || ends[k].key == end.key;
        if (!seen) ends[count++] = end;
    }
    Piece piece;
    if (count == 0) {
        // Only rounding can leave no end (a nearly flat triangle's located features): the
        // overlap of the two spans, in double.
        const auto [a_lo, a_hi] = span(on_a, na, direction);
        const auto [b_lo, b_hi] = span(on_b, nb, direction);
        ends[0] = direction.dot(a_lo.point) >= direction.dot(b_lo.point) ? a_lo : b_lo;
        ends[1] = direction.dot(a_hi.point) <= direction.dot(b_hi.point) ? a_hi : b_hi;
        count = ends[0].key == ends[1].key ? 1 : 2;
    } else if (count > 2) {
        // More than two distinct features (a degenerate pair): the two outermost along the line.
        const auto by_position = [&](const End& x, const End& y) { return direction.dot(x.point) < direction.dot(y.point); };
        const auto [lo, hi] = std::minmax_element(ends.begin(), ends.begin() + count, by_position);
        const End first = *lo, last = *hi;
        ends[0] = first;
        ends[1] = last;
        count = 2;
    }
    if (count == 1) {
        piece.ends = {ends[0].point, ends[0].point};
    } else {
        // A segment joins two features even when it rounds to no length (a curve passing
        // within an ulp of a vertex crosses two of its edges there): it keeps the chain whole.
        piece.kind = Kind::Segment;
        piece.ends = {ends[0].point, ends[1].point};
        piece.keys = {ends[0].key, ends[1].key};
    }
    if (polygon) {
        polygon->assign(piece.ends.begin(), piece.ends.begin() + (piece.kind == Kind::Segment ? 2 : 1));
    }
    return piece;
}

// A triangle clipped by three half-planes keeps at most 6 corners: fixed buffers.
template <typename Point>
struct Clipped {
    std::array<Point, 8> corners;
    std::size_t size = 0;
    void push(const Point& p) { corners[size++] = p; }
};

// Triangle a clipped by triangle b (Sutherland-Hodgman) in the coordinates (u, v) of their
// points; the other coordinates of a 3D point are interpolated along. The result is one of
// the two buffers.
template <typename Point>
Clipped<Point>& clip(const std::array<Point, 3>& a, const std::array<Point, 3>& b, int u, int v,
                     Clipped<Point> (&buffers)[2]) {
    const auto cross2 = [&](const Point& p, const Point& q, const Point& r) {
        return (q[u] - p[u]) * (r[v] - p[v]) - (q[v] - p[v]) * (r[u] - p[u]);
    };
    const double orientation = cross2(b[0], b[1], b[2]) >= 0 ? 1.0 : -1.0;
    Clipped<Point>* clipped = &buffers[0];
    Clipped<Point>* next = &buffers[1];
    clipped->size = 0;
    for (const Point& corner : a) clipped->push(corner);
    for (int e = 0; e < 3 && clipped->size > 0; ++e) {
        const Point& p = b[e];
        const Point& q = b[(e + 1) % 3];
        next->size = 0;
        double ds = orientation * cross2(p, q, clipped->corners[0]);
        for (std::size_t i = 0; i < clipped->size; ++i) {
            const Point& s = clipped->corners[i];
            const Point& t = clipped->corners[i + 1 == clipped->size ? 0 : i + 1];
            const double dt = orientation * cross2(p, q, t);
            if (ds >= 0) next->push(s);
            if ((ds >= 0) != (dt >= 0) && ds != dt && next->size < next->corners.size()) next->push(s + (ds / (ds - dt)) * (t - s));
            ds = dt;
        }
        std::swap(clipped, next);
    }
    return *clipped;
}

// Coplanar triangles: a clipped by b in their shared plane, in the projection that drops the
// axis of the larger normal's largest component.
Piece coplanar(const Triangle& a, const Triangle& b, std::vector<Vec3>* polygon) {
    const Vec3 na = (a[1] - a[0]).cross(a[2] - a[0]);
    const Vec3 nb = (b[1] - b[0]).cross(b[2] - b[0]);
    const Vec3 normal = na.squaredNorm() >= nb.squaredNorm() ? na : nb;
    int drop = 0;
    normal.cwiseAbs().maxCoeff(&drop);
    Clipped<Vec3> buffers[2];
    Clipped<Vec3>& clipped = clip(a, b, (drop + 1) % 3, (drop + 2) % 3, buffers);
    // Rounding or a degenerate triangle can clip everything away from a pair the exact test
    // found touching: keep a corner of a.
    if (clipped.size == 0) clipped.push(a[0]);
    const std::size_t n = clipped.size;
    Piece piece;
    Vec3 twice_area = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i) twice_area += clipped.corners[i].cross(clipped.corners[(i + 1) % n]);
    piece.area = n >= 3 ? 0.5 * twice_area.norm() : 0.0;
    piece.kind = n >= 3 ? Kind::Polygon : n == 2 ? Kind::Segment : Kind::Point;
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < n; ++i) box.extend(clipped.corners[i]);
    piece.ends = {box.min(), box.max()};
    if (piece.kind != Kind::Polygon) piece.ends = {clipped.corners[0], clipped.corners[n - 1]};
    if (polygon) polygon->assign(clipped.corners.begin(), clipped.corners.begin() + static_cast<std::ptrdiff_t>(n));
    return piece;
}

// The axis (0, 1 or 2) whose coordinate all six corners share exactly (both triangles in one
// axis-aligned plane: a floor, sheets at rest), or -1. Every orient3d of such points is 0.
int shared_axis(const Triangle& a, const Triangle& b) {
    for (int k = 0; k < 3; ++k) {
        const double c = a[0][k];
        if (a[1][k] == c && a[2][k] == c && b[0][k] == c && b[1][k] == c && b[2][k] == c) return k;
    }
    return -1;
}

// coplanar() for triangles in the plane x_k = c: the clip in 2D, the points lifted back with
// x_k = c (which the 3D clip's interpolation also gives exactly).
Piece coplanar_in_axis_plane(const Triangle& a, const Triangle& b, int k, std::vector<Vec3>* polygon) {
    using Point = Eigen::Vector2d;
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    const auto flat = [&](const Vec3& p) { return Point(p[u], p[v]); };
    const double c = a[0][k];
    const auto lift = [&](const Point& p) {  // scalar stores and loads (no partial-store stall)
        return k == 0 ? Vec3(c, p[0], p[1]) : k == 1 ? Vec3(p[1], c, p[0]) : Vec3(p[0], p[1], c);
    };
    Clipped<Point> buffers[2];
    Clipped<Point>& clipped =
        clip<Point>({flat(a[0]), flat(a[1]), flat(a[2])}, {flat(b[0]), flat(b[1]), flat(b[2])}, 0, 1, buffers);
    if (clipped.size == 0) clipped.push(flat(a[0]));
    const std::size_t n = clipped.size;
    Piece piece;
    double twice_area = 0;
    Point lo = clipped.corners[0], hi = clipped.corners[0];
    for (std::size_t i = 0; i < n; ++i) {
        const Point& p = clipped.corners[i];
        const Point& q = clipped.corners[i + 1 == n ? 0 : i + 1];
        twice_area += p[0] * q[1] - p[1] * q[0];
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    piece.area = n >= 3 ? 0.5 * std::abs(twice_area) : 0.0;
    piece.kind = n >= 3 ? Kind::Polygon : n == 2 ? Kind::Segment : Kind::Point;
    piece.ends = piece.kind == Kind::Polygon ? std::array{lift(lo), lift(hi)} : std::array{lift(clipped.corners[0]), lift(clipped.corners[n - 1])};
    if (polygon) {
        polygon->clear();
        for (std::size_t i = 0; i < n; ++i) polygon->push_back(lift(clipped.corners[i]));
    }
    return piece;
}

// The generic case, every vertex strictly off the other plane: each triangle has one vertex
// alone on its side and crosses the other plane on the two edges from it. The four
// orientations of those edges against each other decide which of the four crossing points lie
// in the other triangle (Guigue and Devillers' interval test, exact); a zero among them (a
// curve through an edge-edge crossing) is left to the general path. Only the two ends are
// constructed.
bool generic_crossing(const Triangle& a, const TriIndices& ia, const Triangle& b, const TriIndices& ib,
                      const TrianglePair& pair, const std::array<int, 3>& sa, const std::array<int, 3>& sb, Piece& piece) {
    const auto lone = [](const std::array<int, 3>& s) { return s[0] != s[1] ? (s[0] != s[2] ? 0 : 1) : 2; };
    const int p = lone(sa), r = lone(sb);
    // Each triangle's crossing edges, oriented along its cycle: (p, p+1) and (p+2, p).
    const std::array<std::array<int, 2>, 2> ea = {{{p, (p + 1) % 3}, {(p + 2) % 3, p}}};
    const std::array<std::array<int, 2>, 2> eb = {{{r, (r + 1) % 3}, {(r + 2) % 3, r}}};
    int d[2][2];
    for (int x = 0; x < 2; ++x) {
        for (int y = 0; y < 2; ++y) {
            d[x][y] = orient(a[ea[x][0]], a[ea[x][1]], b[eb[y][0]], b[eb[y][1]]);
            if (d[x][y] == 0) return false;
        }
    }
    // A point of edge (u, v) in the other triangle's plane is on the inner side of that
    // triangle's cyclic edge (c, e) when -orient3d(c, e, u, v) has the sign of u's side.
    std::array<End, 4> ends{};
    int count = 0;
    for (int x = 0; x < 2; ++x) {
        if (-d[x][0] * sa[ea[x][0]] > 0 && -d[x][1] * sa[ea[x][0]] > 0) {
            const Vec3& u = a[ea[x][0]];
            const Vec3& v = a[ea[x][1]];
            const Feature edge{pair.obj_a, Feature::Edge, std::min(ia[ea[x][0]], ia[ea[x][1]]), std::max(ia[ea[x][0]], ia[ea[x][1]])};
            ends[count++] = {u + crossing_parameter(u, v, b) * (v - u),
                             make_key(edge, {pair.obj_b, Feature::Face, pair.tri_b, 0}), true};
        }
    }
    for (int y = 0; y < 2; ++y) {
        if (-d[0][y] * sb[eb[y][0]] > 0 && -d[1][y] * sb[eb[y][0]] > 0) {
            const Vec3& u = b[eb[y][0]];
            const Vec3& v = b[eb[y][1]];
            const Feature edge{pair.obj_b, Feature::Edge, std::min(ib[eb[y][0]], ib[eb[y][1]]), std::max(ib[eb[y][0]], ib[eb[y][1]])};
            ends[count++] = {u + crossing_parameter(u, v, a) * (v - u),
                             make_key(edge, {pair.obj_a, Feature::Face, pair.tri_a, 0}), true};
        }
    }
    if (count != 2) return false;  // not a crossing pair after all: the general path decides
    piece.kind = Kind::Segment;
    piece.ends = {ends[0].point, ends[1].point};
    piece.keys = {ends[0].key, ends[1].key};
    return true;
}

// The signs of t's corners against the plane of `plane`: orient3d of each. Where the plane's
// corners share one coordinate exactly (a floor, a box face, a sheet at rest: where exact
// coplanarity is common in floating point), the determinant factors exactly: with the shared
// coordinate k = c, orient3d(p0, p1, p2, x) = sign(c - x_k) * orient2d(p0, p1, p2) in the
// projection dropping k (its cyclic order (k + 1, k + 2)), so three comparisons and one 2D
// orientation replace three 3D ones whose filter cannot decide a zero.
}  // namespace

std::array<int, 3> plane_sides(const std::array<Vec3, 3>& plane, const std::array<Vec3, 3>& t, bool fast) {
    for (int k = 0; fast && k < 3; ++k) {
        const double c = plane[0][k];
        if (plane[1][k] != c || plane[2][k] != c) continue;
        const int turn = orient2d(plane[0], plane[1], plane[2], k);
        if (turn == 0) break;  // a flat triangle: the general predicate
        const auto side = [&](const Vec3& x) { return turn * ((c > x[k]) - (c < x[k])); };
        return {side(t[0]), side(t[1]), side(t[2])};
    }
    return {orient(plane[0], plane[1], plane[2], t[0]), orient(plane[0], plane[1], plane[2], t[1]),
            orient(plane[0], plane[1], plane[2], t[2])};
}

Piece intersect(const Frame& frame, const TrianglePair& pair, std::vector<Vec3>* polygon, bool fast) {
    const ObjectFrame& object_a = frame.objects[pair.obj_a];
    const ObjectFrame& object_b = frame.objects[pair.obj_b];
    const Triangle a = object_a.corners(pair.tri_a);
    const Triangle b = object_b.corners(pair.tri_b);
    if (fast) {
        if (const int axis = shared_axis(a, b); axis >= 0) return coplanar_in_axis_plane(a, b, axis, polygon);
    }
    const std::array<int, 3> sa = plane_sides(b, a, fast);
    const std::array<int, 3> sb = plane_sides(a, b, fast);
    const auto with_sides = [&](Piece piece) {
        for (int k = 0; k < 3; ++k) {
            piece.sides_a[k] = static_cast<std::int8_t>(sa[k]);
            piece.sides_b[k] = static_cast<std::int8_t>(sb[k]);
        }
        return piece;
    };
    const bool flat_a = sa == std::array<int, 3>{0, 0, 0};
    const bool flat_b = sb == std::array<int, 3>{0, 0, 0};
    if (flat_a || flat_b) return with_sides(coplanar(a, b, polygon));
    const TriIndices& ia = object_a.topology->triangles[pair.tri_a];
    const TriIndices& ib = object_b.topology->triangles[pair.tri_b];
    Piece piece;
    if (fast && sa[0] * sa[1] * sa[2] != 0 && sb[0] * sb[1] * sb[2] != 0 && generic_crossing(a, ia, b, ib, pair, sa, sb, piece)) {
        if (polygon) polygon->assign(piece.ends.begin(), piece.ends.end());
        return with_sides(piece);
    }
    return with_sides(crossing(a, ia, b, ib, pair, sa, sb, polygon));
}

}  // namespace collidescope::regions

namespace collidescope {

PairIntersection intersect_pair(const Frame& frame, const TrianglePair& pair) {
    PairIntersection result;
    const regions::Piece piece = regions::intersect(frame, pair, &result.points);
    result.kind = piece.kind;
    result.area = piece.area;
    return result;
}

}  // namespace collidescope
