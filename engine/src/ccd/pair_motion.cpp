// A pair over an interval: the exact test at t = 0; then each vertex of one triangle against
// the other's face and each edge against each edge, every query first through the box of its
// points over the times the triangles' boxes can meet (the motion is linear, so the features
// stay in the convex hull of their positions at those times' ends: boxes apart, no contact),
// and each asked only for contacts before the earliest found so far (and through the boxes up
// to that time).

#include "ccd/pair_motion.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

namespace collidescope::ccd {
namespace {

// The boxes of the pair's six corners over a span of times [from, until] within [0, 1] (empty
// when from > until), and of each triangle's three. A linearly moving point's box: at both
// ends of the interval, and where the span is shorter, the box of its positions at the span's
// ends, each one computed (unless it is an end of the interval) and widened by its rounding
// (fl(p0 + t fl(p1 - p0)) is within about 7u `largest` of exact for t in [0, 1], `largest`
// bounding every coordinate's magnitude; 16u largest covers it, 64 subnormals the products
// that underflow). Never larger than the whole interval's box, so a feature pair that box
// parts stays parted. Plain arrays, one row per axis, each written once per fit: built as
// boxes of vectors and copied, their stores were most of a fit's time, a sixth of the pair's
// on coplanar-stack.
struct FeatureBoxes {
    std::array<std::array<double, 6>, 3> lo, hi;  ///< [axis][corner]: a's corners 0-2, b's 3-5
    std::array<std::array<double, 3>, 2> face_lo, face_hi;  ///< [triangle][axis]

    void fit(const PairMotion& m, double from, double until, double largest) {
        if (from > until) {  // no time: every box empty, so none meets another
            constexpr double k_inf = std::numeric_limits<double>::infinity();
            for (auto& row : lo) row.fill(k_inf);
            for (auto& row : hi) row.fill(-k_inf);
            for (auto& row : face_lo) row.fill(k_inf);
            for (auto& row : face_hi) row.fill(-k_inf);
            return;
        }
        const bool whole = from <= 0 && until >= 1;
        const double margin = 16 * std::numeric_limits<double>::epsilon() / 2 * largest + 64 * std::numeric_limits<double>::denorm_min();
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < 6; ++c) {
                const Path& path = c < 3 ? m.a[c] : m.b[c - 3];
                const double p0 = path[0][k], p1 = path[1][k];
                double low = std::min(p0, p1), high = std::max(p0, p1);
                if (!whole) {
                    const auto at = [&](double t, double& a_lo, double& a_hi) {
                        if (t <= 0 || t >= 1) {
                            a_lo = a_hi = t <= 0 ? p0 : p1;
                        } else {
                            const double x = p0 + t * (p1 - p0);
                            a_lo = x - margin, a_hi = x + margin;
                        }
                    };
                    double from_lo, from_hi, until_lo, until_hi;
                    at(from, from_lo, from_hi);
                    at(until, until_lo, until_hi);
                    low = std::max(low, std::min(from_lo, until_lo));
                    high = std::min(high, std::max(from_hi, until_hi));
                }
                lo[k][c] = low;
                hi[k][c] = high;
            }
            for (int t = 0; t < 2; ++t) {
                face_lo[t][k] = std::min({lo[k][3 * t], lo[k][3 * t + 1], lo[k][3 * t + 2]});
                face_hi[t][k] = std::max({hi[k][3 * t], hi[k][3 * t + 1], hi[k][3 * t + 2]});
            }
        }
    }
    /// Whether corner c (0-5) meets the other triangle's box.
    bool corner_meets_face(int c) const {
        const int t = c < 3 ? 1 : 0;
        bool meets = true;
        for (int k = 0; k < 3; ++k) meets = meets && lo[k][c] <= face_hi[t][k] && face_lo[t][k] <= hi[k][c];
        return meets;
    }
    /// Whether edge (a0, a1) of a meets edge (b0, b1) of b (corner indices 0-2 of each).
    bool edges_meet(int a0, int a1, int b0, int b1) const {
        bool meets = true;
        for (int k = 0; k < 3; ++k) {
            const double a_lo = std::min(lo[k][a0], lo[k][a1]), a_hi = std::max(hi[k][a0], hi[k][a1]);
            const double b_lo = std::min(lo[k][3 + b0], lo[k][3 + b1]), b_hi = std::max(hi[k][3 + b0], hi[k][3 + b1]);
            meets = meets && a_lo <= b_hi && b_lo <= a_hi;
        }
        return meets;
    }
};

// The exact per-frame test at one end; `planar`: all twelve positions lie in one plane (and
// the triangles share no vertex, where the self rule is triangles_intersect).
bool touching(const PairMotion& m, int end, bool planar) {
    const std::array<Vec3, 3> a{m.a[0][end], m.a[1][end], m.a[2][end]};
    const std::array<Vec3, 3> b{m.b[0][end], m.b[1][end], m.b[2][end]};
    if (planar) return coplanar_triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
    if (m.self) return self_triangles_collide(m.ia, a, m.ib, b);
    return triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

bool shares(const TriIndices& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

// The twelve positions: both triangles at both ends.
std::array<Vec3, 12> positions(const PairMotion& m) {
    std::array<Vec3, 12> points;
    for (int i = 0; i < 3; ++i) {
        for (int end = 0; end < 2; ++end) {
            points[i * 2 + end] = m.a[i][end];
            points[6 + i * 2 + end] = m.b[i][end];
        }
    }
    return points;
}

// The common case of a plane holding the motion (below), cheap enough to ask of every pair: one
// coordinate shared by all twelve positions (that axis), else -1.
int shared_coordinate(const PairMotion& m) {
    const auto same = [&](int k) {
        const double value = m.a[0][0][k];
        for (const std::array<Path, 3>* t : {&m.a, &m.b}) {
            for (const Path& path : *t) {
                if (path[0][k] != value || path[1][k] != value) return false;  // most pairs: at once
            }
        }
        return true;
    };
    for (int k = 0; k < 3; ++k) {
        if (same(k)) return k;
    }
    return -1;
}

// The general case, asked once shared_coordinate has said no: when all twelve positions (both
// triangles at both ends) lie in one plane, decided exactly, an axis the plane's normal has a
// non-zero component along (else -1): then every position in
// between lies in the plane too (an affine combination of them), and two triangles in a plane
// that first touch do so with a vertex of one on the other's border, so the vertex-face
// queries, in their planar form, find every first contact and the edge-edge ones (whose zero
// sets, for nearly parallel edges in a plane, are long curves that cost the inclusion search
// dearly) are not needed. Not for two triangles of one object sharing a vertex: the self rule skips the
// queries of shared vertices, and such a pair can start to overlap at a shared vertex (one
// triangle folding through it) where only an edge-edge query sees it.
int coplanar_motion(const PairMotion& m) {
    const std::array<Vec3, 12> points = positions(m);
    // A plane: the first point and two more that make a non-degenerate triangle with it.
    for (int i = 1; i < 12; ++i) {
        for (int j = i + 1; j < 12; ++j) {
            // Not on one line, decided exactly: a non-zero orientation in some projection.
            int drop = 0;
            while (drop < 3 && orient2d(points[0], points[i], points[j], drop) == 0) ++drop;
            if (drop == 3) continue;
            for (int k = 1; k < 12; ++k) {  // the plane's own three points are in it
                if (k != i && k != j && orient3d(points[0], points[i], points[j], points[k]) != 0) return -1;
            }
            return drop;
        }
    }
    return -1;  // all on a line or a point: the general queries decide
}

// Whether the corners of `points` (those not shared with `face`, for self: the shared ones lie
// in its plane) stay strictly on one side of the moving plane of `face` throughout the
// interval. Then the triangle of `points` meets the other's plane only within the hull of the
// shared corners (nowhere, when none is shared) at every time: no contact, or only one that
// the self rule does not count, and none of the queries needs to run. A face that degenerates
// to a line at some time has no side there: its signed volumes vanish, and nothing is skipped.
bool separated(const std::array<Path, 3>& points, const TriIndices& point_ids, const std::array<Path, 3>& face,
               const TriIndices& face_ids, bool self, double largest) {
    MovingPlane plane(face[0], face[1], face[2], largest);
    int side = 0;
    for (int i = 0; i < 3; ++i) {
        if (self && shares(face_ids, point_ids[i])) continue;
        const int s = plane.side(points[i]);
        if (s == 0 || (side != 0 && s != side)) return false;
        side = s;
    }
    return side != 0;
}

// Whether two sets of linearly moving points (corners of features) stay apart along the fixed
// direction d throughout the interval: the gap g(t) = min_j y_j(t).d - max_i x_i(t).d is the
// minimum of linear functions less the maximum of linear functions, so concave in t, and it
// is positive on all of [0, 1] when it is at both ends (the same for x above y). Each gap is
// taken beyond a static bound of its rounding: with `largest` at least every coordinate's
// magnitude, a dot product errs by at most 3u largest |d|_1 (u = 2^-53), a difference of two by
// twice that plus u of the result; 16u largest |d|_1 covers it, and 64 subnormals cover products
// that underflow. Every value is at most largest |d|_1 in magnitude, so none overflows while that
// stays below 1e300; where it does not (a normal times an edge grows as a coordinate's cube, and
// its products overflowed at coordinates of 1e77), d is scaled to a largest component of 1 first:
// d itself needs no accuracy, any direction is one.
template <std::size_t N, std::size_t M>
bool apart_along(const std::array<const Path*, N>& x, const std::array<const Path*, M>& y, const Vec3& direction,
                 double largest) {
    constexpr double k_range = 1e300;
    Vec3 d = direction;
    double reach = largest * d.cwiseAbs().sum();
    if (!(reach < k_range)) {
        const double scale = d.cwiseAbs().maxCoeff();
        if (!(scale > 0) || !(scale < std::numeric_limits<double>::infinity())) return false;
        d /= scale;
        reach = largest * d.cwiseAbs().sum();
        if (!(reach < k_range)) return false;
    }
    const double error = 16 * std::numeric_limits<double>::epsilon() / 2 * reach + 64 * std::numeric_limits<double>::denorm_min();
    bool x_below = true, y_below = true;
    for (int end = 0; end < 2 && (x_below || y_below); ++end) {
        double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
        for (const Path* p : x) {
            const double v = (*p)[end].dot(d);
            x_lo = std::min(x_lo, v);
            x_hi = std::max(x_hi, v);
        }
        for (const Path* p : y) {
            const double v = (*p)[end].dot(d);
            y_lo = std::min(y_lo, v);
            y_hi = std::max(y_hi, v);
        }
        x_below = x_below && y_lo - x_hi > error;
        y_below = y_below && x_lo - y_hi > error;
    }
    return x_below || y_below;
}

std::array<const Path*, 3> corners_of(const std::array<Path, 3>& t) { return {&t[0], &t[1], &t[2]}; }

// Directions that often part two triangles that do not touch when the planes' sides do not
// (above all two triangles moving in one plane, side by side): from one centroid to the other
// and each edge's normal within its triangle's plane, at t = `end`.
bool triangles_apart(const PairMotion& m, double largest, int end) {
    const auto a = corners_of(m.a), b = corners_of(m.b);
    const Vec3 ca = m.a[0][end] + m.a[1][end] + m.a[2][end];
    const Vec3 cb = m.b[0][end] + m.b[1][end] + m.b[2][end];
    if (apart_along(a, b, cb - ca, largest)) return true;
    for (const std::array<Path, 3>* t : {&m.a, &m.b}) {
        const std::array<Path, 3>& c = *t;
        const Vec3 normal = (c[1][end] - c[0][end]).cross(c[2][end] - c[0][end]);
        for (int i = 0; i < 3; ++i) {
            if (apart_along(a, b, normal.cross(c[(i + 1) % 3][end] - c[i][end]), largest)) return true;
        }
    }
    return false;
}

// The largest magnitude of a coordinate of these paths (a query's own: its filter's bound then
// depends on its features alone, as a stored result must).
double largest_of(std::initializer_list<const Path*> paths) {
    double largest = 0;
    for (const Path* path : paths) largest = std::max({largest, (*path)[0].cwiseAbs().maxCoeff(), (*path)[1].cwiseAbs().maxCoeff()});
    return largest;
}

// A vertex that stays clear of a face: apart along each of the face's edge normals within its
// plane, or along the line from the face's centroid to the vertex, at t = 0.
bool vertex_clear_of_face(const Path& p, const std::array<Path, 3>& face, double largest) {
    const std::array<const Path*, 1> vertex{&p};
    const auto corners = corners_of(face);
    const Vec3 normal = (face[1][0] - face[0][0]).cross(face[2][0] - face[0][0]);
    for (int i = 0; i < 3; ++i) {
        if (apart_along(vertex, corners, normal.cross(face[(i + 1) % 3][0] - face[i][0]), largest)) return true;
    }
    return apart_along(vertex, corners, p[0] - (face[0][0] + face[1][0] + face[2][0]) / 3, largest);
}

// Two edges apart along their common normal or the line between their midpoints, at t = 0.
bool edges_clear(const Path& p0, const Path& p1, const Path& q0, const Path& q1, double largest) {
    const std::array<const Path*, 2> e{&p0, &p1}, f{&q0, &q1};
    return apart_along(e, f, (p1[0] - p0[0]).cross(q1[0] - q0[0]), largest) ||
           apart_along(e, f, q0[0] + q1[0] - p0[0] - p1[0], largest);
}

}  // namespace

namespace {

// A bound above an exact difference x - y of doubles from its rounded value d = fl(x - y):
// |x - y - d| <= u |x - y| < 2u |d| (exact when d is 0 or subnormal), and adding 4u |d|
// rounds by at most u of a value below 2 |d|: never below x - y.
double above_difference(double d) { return d + std::abs(d) * 0x1p-51; }

}  // namespace

OverlapWindow overlap_window(const PairMotion& m) {
    OverlapWindow window;
    for (int k = 0; k < 3; ++k) {
        std::array<double, 2> a_lo, a_hi, b_lo, b_hi;
        for (int end = 0; end < 2; ++end) {
            a_lo[end] = std::min({m.a[0][end][k], m.a[1][end][k], m.a[2][end][k]});
            a_hi[end] = std::max({m.a[0][end][k], m.a[1][end][k], m.a[2][end][k]});
            b_lo[end] = std::min({m.b[0][end][k], m.b[1][end][k], m.b[2][end][k]});
            b_hi[end] = std::max({m.b[0][end][k], m.b[1][end][k], m.b[2][end][k]});
        }
        // The gap functions that must not be negative for the boxes to meet: A's top above
        // B's bottom, and B's top above A's bottom. Each is at most the line through its upper
        // bounds at the ends, h(t) = (1 - t) h0 + t h1, which is negative before or after
        // its root t* (or throughout).
        for (const auto& [top, bottom] : {std::pair{&a_hi, &b_lo}, std::pair{&b_hi, &a_lo}}) {
            const double h0 = above_difference((*top)[0] - (*bottom)[0]);
            const double h1 = above_difference((*top)[1] - (*bottom)[1]);
            if (h0 >= 0 && h1 >= 0) continue;
            if (h0 < 0 && h1 < 0) return {1, 0};
            // t* = h0 / (h0 - h1), its quotient rounded within 3u of it (the sum and the
            // division: both operands of the sum have one sign), moved past that by 2^-50 of
            // itself and 2^-1000 (for quotients that underflow).
            const double root = h0 < 0 ? -h0 / (h1 + -h0) : h0 / (h0 + -h1);
            if (h0 < 0) {
                window.lo = std::max(window.lo, root - root * 0x1p-50 - 0x1p-1000);  // rising: from t*
            } else {
                window.hi = std::min(window.hi, root + root * 0x1p-50 + 0x1p-1000);  // falling: until t*
            }
        }
    }
    return window;
}

PairOutcome test_pair(const PairMotion& m, double tolerance, std::uint32_t max_boxes, QueryCache* cache) {
    PairOutcome out;
    if (m.self && std::is_permutation(m.ia.begin(), m.ia.end(), m.ib.begin())) return out;  // the same triangle
    // The cheapest filter first: the times the boxes can meet (none: apart). Two triangles of
    // one object sharing a vertex always meet there: the whole interval.
    const bool sharing = m.self && (shares(m.ib, m.ia[0]) || shares(m.ib, m.ia[1]) || shares(m.ib, m.ia[2]));
    const OverlapWindow window = sharing ? OverlapWindow{} : overlap_window(m);
    if (window.empty()) return out;
    double largest = 0;
    for (int i = 0; i < 3; ++i) {
        for (int end = 0; end < 2; ++end) largest = std::max({largest, m.a[i][end].cwiseAbs().maxCoeff(), m.b[i][end].cwiseAbs().maxCoeff()});
    }
    // In one plane the planes' sides are zero and the fixed directions seldom part a pair (on
    // dense coplanar contact they cost more than they saved): the planar queries decide. The
    // plane's common case (one coordinate shared) is asked first; the general exact test only
    // of the pairs that reach the queries (on a character, whose neighbouring triangles are
    // nearly coplanar, its exact orientations are costly).
    if (separated(m.b, m.ib, m.a, m.ia, m.self, largest) || separated(m.a, m.ia, m.b, m.ib, m.self, largest)) return out;
    int plane_axis = sharing ? -1 : shared_coordinate(m);
    // The fixed directions (not for two triangles of one object sharing a vertex: those are
    // never apart along one) at t = 0 first; those at t = 1 part few more pairs (data set A:
    // 10k of 236k parted), so they are asked only of a pair the queries then report without
    // touching at either end, the only kind they could part (a grazing pair accepted within δ).
    const bool directions = plane_axis < 0 && !sharing;
    if (directions && triangles_apart(m, largest, 0)) return out;
    if (touching(m, 0, plane_axis >= 0)) {
        out.contact = out.start_contact = true;
        out.toi = 0;
        out.end_contact = touching(m, 1, plane_axis >= 0);
        return out;
    }
    if (!sharing && plane_axis < 0) plane_axis = coplanar_motion(m);
    const bool planar = plane_axis >= 0;
    // The features' boxes over the window's times up to config.t_max: the whole window,
    // then, once a contact is known, only up to it (only an earlier contact matters then; on
    // data set A 30% of the queries asked after a contact have features apart until it).
    // Outside the window the triangles are apart, so a query whose features these boxes part
    // has no contact to find (the queries themselves still search the whole interval up to
    // t_max: a stored result is the whole interval's).
    FeatureBoxes boxes;
    const auto fit_bounds = [&](double until) { boxes.fit(m, window.lo, std::min(until, window.hi), largest); };
    fit_bounds(1);
    double bounds_until = window.hi;  // the boxes end there: a contact after it changes nothing
    QueryConfig config{tolerance, 1, max_boxes};
    // Once a query has found contact, the others only ask whether there is an earlier one, on
    // a smaller budget: spent, its earliest time not excluded becomes the pair's toi (still a
    // lower bound; the pair is then marked unresolved).
    constexpr std::uint32_t k_after_contact = 4096;
    const auto record = [&](const QueryResult& r) {
        ++out.queries;
        out.boxes += r.boxes;
        if (!r.hit) return;
        if (!out.contact || r.toi < out.toi) out.toi = r.toi;
        out.contact = true;
        out.resolved = out.resolved && r.resolved;
        config.t_max = out.toi;  // only an earlier contact matters now
        config.max_boxes = std::min(max_boxes, k_after_contact);
    };
    const auto refit_bounds = [&] {
        if (config.t_max < bounds_until) {
            bounds_until = config.t_max;
            fit_bounds(bounds_until);
        }
    };
    // A query through the cache (where its features recur across pairs): its filter (fixed
    // directions at t = 0) and its solution over the whole interval are pure functions of its
    // key, so both are stored, and a query found there is not asked again. After the pair has a
    // contact a query is solved only up to it, on the smaller budget, as without a cache, and
    // not stored (a stored whole-interval solution would count other boxes). So the pair's
    // outcome and its counts are the same with or without a cache, whatever it held. Returns
    // nothing for a query its filter clears.
    const auto ask = [&](const QueryKey& key, bool recurs, const auto& clear, const auto& solve) -> std::optional<QueryResult> {
        if (cache == nullptr || !recurs) {
            if (clear()) return std::nullopt;
            return solve(config);
        }
        const CachedQuery* found = cache->find(key);
        if (found != nullptr && found->cleared) return std::nullopt;
        if (found == nullptr && clear()) {
            cache->insert(key, {QueryResult{}, true});
            return std::nullopt;
        }
        if (out.contact) return solve(config);
        if (found != nullptr) return found->result;
        const QueryResult result = solve(config);  // the whole interval, the full budget
        cache->insert(key, {result, false});
        return result;
    };
    const auto vertex_query = [&](std::uint32_t vertex_object, std::uint32_t v, const Path& p, std::uint32_t face_object,
                                  std::uint32_t tri, const std::array<Path, 3>& face) {
        const bool recurs = vertex_object == m.object_a ? m.shares_a : m.shares_b;
        return ask(
            QueryKey::vertex_face(vertex_object, v, face_object, tri, planar ? plane_axis : -1), recurs,
            [&] { return !planar && vertex_clear_of_face(p, face, largest_of({&p, &face[0], &face[1], &face[2]})); },
            [&](const QueryConfig& c) {
                return planar ? vertex_face_in_plane(p, face[0], face[1], face[2], plane_axis, c)
                              : vertex_face(p, face[0], face[1], face[2], c);
            });
    };
    // Each edge with its smaller vertex index first, the two in (object, indices) order: the
    // same query whichever pair asks it.
    const auto edge_query = [&](std::uint32_t p_object, std::uint32_t p0, std::uint32_t p1, const Path* pp0, const Path* pp1,
                                std::uint32_t q_object, std::uint32_t q0, std::uint32_t q1, const Path* pq0, const Path* pq1) {
        if (p1 < p0) std::swap(p0, p1), std::swap(pp0, pp1);
        if (q1 < q0) std::swap(q0, q1), std::swap(pq0, pq1);
        if (std::tie(q_object, q0, q1) < std::tie(p_object, p0, p1)) {
            std::swap(p_object, q_object), std::swap(p0, q0), std::swap(p1, q1), std::swap(pp0, pq0), std::swap(pp1, pq1);
        }
        return ask(
            QueryKey::edge_edge(p_object, p0, p1, q_object, q0, q1), m.shares_a || m.shares_b,
            [&] { return edges_clear(*pp0, *pp1, *pq0, *pq1, largest_of({pp0, pp1, pq0, pq1})); },
            [&](const QueryConfig& c) { return edge_edge(*pp0, *pp1, *pq0, *pq1, c); });
    };
    const auto record_if = [&](const std::optional<QueryResult>& r) {
        if (r) record(*r);
    };
    // Each vertex of one against the other's face (not a vertex of that face, for self).
    for (int i = 0; i < 3; ++i) {
        refit_bounds();
        if (!(m.self && shares(m.ib, m.ia[i])) && boxes.corner_meets_face(i)) {
            record_if(vertex_query(m.object_a, m.ia[i], m.a[i], m.object_b, m.tri_b, m.b));
        }
        refit_bounds();
        if (!(m.self && shares(m.ia, m.ib[i])) && boxes.corner_meets_face(3 + i)) {
            record_if(vertex_query(m.object_b, m.ib[i], m.b[i], m.object_a, m.tri_a, m.a));
        }
    }
    // Each edge against each edge (not sharing a vertex, for self), unless in one plane.
    for (int i = 0; i < 3 && !planar; ++i) {
        const int i1 = (i + 1) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3;
            if (m.self && (m.ia[i] == m.ib[j] || m.ia[i] == m.ib[j1] || m.ia[i1] == m.ib[j] || m.ia[i1] == m.ib[j1])) continue;
            refit_bounds();
            if (boxes.edges_meet(i, i1, j, j1)) {
                record_if(edge_query(m.object_a, m.ia[i], m.ia[i1], &m.a[i], &m.a[i1], m.object_b, m.ib[j], m.ib[j1], &m.b[j],
                                     &m.b[j1]));
            }
        }
    }
    if (out.contact) out.end_contact = touching(m, 1, planar);
    if (out.contact && !out.end_contact && directions && triangles_apart(m, largest, 1)) {
        PairOutcome apart;  // no contact, but the queries' work counted
        apart.queries = out.queries;
        apart.boxes = out.boxes;
        return apart;
    }
    return out;
}

}  // namespace collidescope::ccd
