// The CCD peer's root-finding narrow phase (ccd_root_finding.hpp says what and why).

#include "peers/ccd_root_finding.hpp"

#include "collidescope/geometry.hpp"

#include <Eigen/Geometry>  // cross

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::peers {
namespace {

// A polynomial whose coefficients are all below this times its bound on [0, 1] is taken as
// zero there (for the cubic: coplanar motion; for a leading coefficient: a lower degree).
// Exactly coplanar scenes (one shared coordinate) give exact zeros; a rotated plane gives
// rounding, about 1e-16 of the bound.
constexpr double k_zero = 1e-12;
// |f| below this times its bound at a critical point: a touching (double) root the sign test
// cannot see, tested as a candidate (the proximity test decides).
constexpr double k_touching = 1e-9;
// The Newton iteration stops when its steps are below this in t.
constexpr double k_t_precision = 1e-13;

Vec3 position(const CcdPath& p, double t) { return p[0] + t * (p[1] - p[0]); }

// y(t) - x(t) as a linear function of t: at0 + t * rate.
struct Linear {
    Vec3 at0, rate;
    double bound() const { return at0.norm() + rate.norm(); }  // |value| on [0, 1]
};

Linear between(const CcdPath& x, const CcdPath& y) { return {y[0] - x[0], (y[1] - y[0]) - (x[1] - x[0])}; }

// Candidate times, kept in a fixed array (at most 10 are added: see the callers).
struct Times {
    std::array<double, 16> t{};
    int n = 0;
    void add_in(double x, double lo, double hi) {
        if (x >= lo && x <= hi && n < static_cast<int>(t.size())) t[n++] = x;
    }
    void sort() { std::sort(t.begin(), t.begin() + n); }
};

// c0 + c1 t + c2 t^2 (+ c3 t^3), with `bound` >= |value| on [0, 1] (the scale of the tests).
struct Poly {
    double c0 = 0, c1 = 0, c2 = 0, c3 = 0, bound = 0;
    double at(double t) const { return ((c3 * t + c2) * t + c1) * t + c0; }
    double slope(double t) const { return (3 * c3 * t + 2 * c2) * t + c1; }
    bool zero() const { return std::max({std::abs(c0), std::abs(c1), std::abs(c2), std::abs(c3)}) <= k_zero * bound; }
};

// det[u v w] of three linear vectors: the coplanarity cubic (Provot; Bridson et al.).
Poly triple(const Linear& u, const Linear& v, const Linear& w) {
    const auto det = [](const Vec3& x, const Vec3& y, const Vec3& z) { return x.dot(y.cross(z)); };
    Poly f;
    f.c0 = det(u.at0, v.at0, w.at0);
    f.c1 = det(u.rate, v.at0, w.at0) + det(u.at0, v.rate, w.at0) + det(u.at0, v.at0, w.rate);
    f.c2 = det(u.rate, v.rate, w.at0) + det(u.rate, v.at0, w.rate) + det(u.at0, v.rate, w.rate);
    f.c3 = det(u.rate, v.rate, w.rate);
    f.bound = u.bound() * v.bound() * w.bound();
    return f;
}

// The 2D orientation of (x, y, z) in the coordinate plane that drops axis `drop`: a quadratic.
Poly orientation(const CcdPath& x, const CcdPath& y, const CcdPath& z, int drop) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const Linear u = between(x, y), v = between(x, z);
    const auto cross = [&](const Vec3& a, const Vec3& b) { return a[i] * b[j] - a[j] * b[i]; };
    Poly q;
    q.c0 = cross(u.at0, v.at0);
    q.c1 = cross(u.at0, v.rate) + cross(u.rate, v.at0);
    q.c2 = cross(u.rate, v.rate);
    q.bound = u.bound() * v.bound();
    return q;
}

// Real roots in [lo, hi] of a t^2 + b t + c, degrading to the linear case when a is negligible
// against `scale`; with no real root, the vertex of the parabola when it nearly touches zero.
void quadratic_roots(double a, double b, double c, double scale, double lo, double hi, Times& out) {
    const double negligible = k_zero * scale;
    if (std::abs(a) <= negligible) {
        if (std::abs(b) > negligible) out.add_in(-c / b, lo, hi);
        return;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) {
        const double t = -b / (2 * a);
        if (std::abs((a * t + b) * t + c) <= k_touching * scale) out.add_in(t, lo, hi);
        return;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));  // no cancellation
    out.add_in(q / a, lo, hi);
    if (q != 0) out.add_in(c / q, lo, hi);
}

// The root of f in [lo, hi], where f changes sign and is monotone: Newton steps, kept inside
// the shrinking bracket, a bisection step whenever Newton would leave it.
double refine(const Poly& f, double lo, double hi) {
    const bool rising = f.at(hi) > 0;
    double t = 0.5 * (lo + hi);
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double value = f.at(t);
        if (value == 0) return t;
        ((value > 0) == rising ? hi : lo) = t;
        const double slope = f.slope(t);
        double next = slope != 0 ? t - value / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = std::abs(next - t);
        t = next;
        if (step < k_t_precision || hi - lo < k_t_precision) break;
    }
    return t;
}

// The cubic's candidate times in [0, t_max], in order: the roots of its monotone pieces and
// the piece ends where it (nearly) touches zero. False when it is zero throughout.
bool cubic_candidates(const Poly& f, double t_max, Times& out) {
    if (f.zero()) return false;
    Times ends;
    ends.add_in(0, 0, t_max);
    quadratic_roots(3 * f.c3, 2 * f.c2, f.c1, f.bound, 0, t_max, ends);  // critical points
    ends.add_in(t_max, 0, t_max);
    ends.sort();
    for (int k = 0; k < ends.n; ++k) {
        if (std::abs(f.at(ends.t[k])) <= k_touching * f.bound) out.add_in(ends.t[k], 0, t_max);
        if (k + 1 < ends.n && ends.t[k] < ends.t[k + 1]) {
            const double a = f.at(ends.t[k]), b = f.at(ends.t[k + 1]);
            if ((a < 0 && b > 0) || (a > 0 && b < 0)) out.add_in(refine(f, ends.t[k], ends.t[k + 1]), 0, t_max);
        }
    }
    out.sort();
    return true;
}

// The axis to drop for a plane holding the query's points: the largest coordinate of the
// largest of `normals` (evaluated at three times, as the plane may turn); -1 when all vanish
// (the points stay on a line).
template <typename Normal>
int drop_axis(Normal&& normal) {
    Vec3 best = Vec3::Zero();
    for (double t : {0.0, 0.5, 1.0}) {
        const Vec3 n = normal(t);
        if (n.squaredNorm() > best.squaredNorm()) best = n;
    }
    if (best.squaredNorm() == 0) return -1;
    int axis = 0;
    best.cwiseAbs().maxCoeff(&axis);
    return axis;
}

// Coplanar motion: candidate times where one point crosses the line of two others, in a
// projection of the plane, and both ends.
template <std::size_t N>
void coplanar_candidates(const std::array<std::array<const CcdPath*, 3>, N>& triples, int drop, double t_max, Times& out) {
    out.add_in(0, 0, t_max);
    out.add_in(t_max, 0, t_max);
    if (drop >= 0) {
        for (const auto& [x, y, z] : triples) {
            const Poly q = orientation(*x, *y, *z, drop);
            quadratic_roots(q.c2, q.c1, q.c0, q.bound, 0, t_max, out);
        }
    }
    out.sort();
}

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double s = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + s * ab - p).norm();
}

// Box of some paths' positions at both ends.
struct Bounds {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
    Bounds& grow(const CcdPath& p) {
        lo = lo.cwiseMin(p[0]).cwiseMin(p[1]);
        hi = hi.cwiseMax(p[0]).cwiseMax(p[1]);
        return *this;
    }
    bool overlaps(const Bounds& o) const { return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all(); }
};

bool touching(const CcdMotion& m, int end) {
    const std::array<Vec3, 3> a{m.a[0][end], m.a[1][end], m.a[2][end]};
    const std::array<Vec3, 3> b{m.b[0][end], m.b[1][end], m.b[2][end]};
    if (m.self) return self_triangles_collide(m.ia, a, m.ib, b);
    return triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

bool shares(const TriIndices& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

}  // namespace

// Ericson, Real-Time Collision Detection 5.1.5 (a degenerate triangle: its edges).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a;
    const double area2 = ab.cross(ac).squaredNorm();
    if (!(area2 > 1e-24 * ab.squaredNorm() * ac.squaredNorm())) {
        return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c), point_segment_distance(p, c, a)});
    }
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return ap.norm();
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return bp.norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (a + d1 / (d1 - d3) * ab - p).norm();
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return cp.norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (a + d2 / (d2 - d6) * ac - p).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b) - p).norm();
    const double denominator = 1 / (va + vb + vc);
    return (a + ab * (vb * denominator) + ac * (vc * denominator) - p).norm();
}

// Ericson 5.1.9 (parallel segments: s = 0, then the clamps find the closest ends).
double segment_segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0, t = 0;
    if (a <= 0 && e <= 0) return r.norm();
    if (a <= 0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= 0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denominator = a * e - b * b;
            s = denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return (p0 + s * d1 - (q0 + t * d2)).norm();
}

std::optional<double> root_vertex_face(const CcdPath& p, const CcdPath& a, const CcdPath& b, const CcdPath& c,
                                       double delta, double t_max) {
    Times times;
    if (!cubic_candidates(triple(between(a, b), between(a, c), between(a, p)), t_max, times)) {
        const int drop = drop_axis([&](double t) {
            return (position(b, t) - position(a, t)).cross(position(c, t) - position(a, t)).eval();
        });
        coplanar_candidates<3>({{{&a, &b, &p}, {&b, &c, &p}, {&c, &a, &p}}}, drop, t_max, times);
    }
    for (int k = 0; k < times.n; ++k) {
        const double t = times.t[k];
        if (point_triangle_distance(position(p, t), position(a, t), position(b, t), position(c, t)) <= delta) return t;
    }
    return std::nullopt;
}

std::optional<double> root_edge_edge(const CcdPath& p0, const CcdPath& p1, const CcdPath& q0, const CcdPath& q1,
                                     double delta, double t_max) {
    Times times;
    if (!cubic_candidates(triple(between(p0, p1), between(q0, q1), between(p0, q0)), t_max, times)) {
        // Zero throughout: the edges stay in one plane (or parallel, or on a line).
        const int drop = drop_axis([&](double t) {
            const Vec3 x0 = position(p0, t), e = position(p1, t) - x0;
            const Vec3 n0 = e.cross(position(q0, t) - x0), n1 = e.cross(position(q1, t) - x0);
            return (n0.squaredNorm() >= n1.squaredNorm() ? n0 : n1).eval();
        });
        coplanar_candidates<4>({{{&p0, &p1, &q0}, {&p0, &p1, &q1}, {&q0, &q1, &p0}, {&q0, &q1, &p1}}}, drop, t_max, times);
    }
    for (int k = 0; k < times.n; ++k) {
        const double t = times.t[k];
        if (segment_segment_distance(position(p0, t), position(p1, t), position(q0, t), position(q1, t)) <= delta) return t;
    }
    return std::nullopt;
}

CcdOutcome root_finding_test_pair(const CcdMotion& m, double delta) {
    CcdOutcome out;
    if (m.self && std::is_permutation(m.ia.begin(), m.ia.end(), m.ib.begin())) return out;  // the same triangle
    if (touching(m, 0)) {
        out.contact = out.start_contact = true;
        out.toi = 0;
        return out;
    }
    Bounds face_a, face_b;
    for (int i = 0; i < 3; ++i) {
        face_a.grow(m.a[i]);
        face_b.grow(m.b[i]);
    }
    // Once a query found contact, the others look only before it (the earliest root is the toi).
    const auto record = [&](std::optional<double> t) {
        if (t && (!out.contact || *t < out.toi)) out.toi = *t;
        out.contact = out.contact || t.has_value();
    };
    const auto t_max = [&] { return out.contact ? out.toi : 1.0; };
    for (int i = 0; i < 3; ++i) {
        if (!(m.self && shares(m.ib, m.ia[i])) && Bounds{}.grow(m.a[i]).overlaps(face_b)) {
            record(root_vertex_face(m.a[i], m.b[0], m.b[1], m.b[2], delta, t_max()));
        }
        if (!(m.self && shares(m.ia, m.ib[i])) && Bounds{}.grow(m.b[i]).overlaps(face_a)) {
            record(root_vertex_face(m.b[i], m.a[0], m.a[1], m.a[2], delta, t_max()));
        }
    }
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3;
        const Bounds edge_a = Bounds{}.grow(m.a[i]).grow(m.a[i1]);
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3;
            if (m.self && (m.ia[i] == m.ib[j] || m.ia[i] == m.ib[j1] || m.ia[i1] == m.ib[j] || m.ia[i1] == m.ib[j1])) continue;
            if (edge_a.overlaps(Bounds{}.grow(m.b[j]).grow(m.b[j1]))) {
                record(root_edge_edge(m.a[i], m.a[i1], m.b[j], m.b[j1], delta, t_max()));
            }
        }
    }
    out.pass_through = out.contact && !touching(m, 1);
    return out;
}

}  // namespace collidescope::peers
