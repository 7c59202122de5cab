// orient3d and orient2d: a static floating-point filter, then cheap exact arguments, then an
// exact fallback.
//
// Filter: the determinant in doubles plus an error bound proportional to its permanent
// (Shewchuk 1997, orient3d errboundA = (7 + 56 eps) eps, orient2d ccwerrboundA =
// (3 + 16 eps) eps); we use 8 eps and 4 eps plus an absolute term, which also covers
// gradual underflow in the products. Cheap exact stage (no expansions; orient3d_cheap says
// why each argument is exact): a repeated point gives 0 symbolically, and a determinant whose
// every operation is exact in doubles is read off its double value. Exact path: the
// determinant as an expansion when every coordinate's magnitude lies in [kSafeMin, kSafeMax]
// (or is zero), where no intermediate can underflow or overflow; GMP rationals otherwise.

#include "collidescope/geometry.hpp"
#include "geometry/adjacent_filter.hpp"
#include "geometry/exact_determinant.hpp"
#include "geometry/expansion.hpp"
#include "geometry/orient2d_filter.hpp"

#include <gmp.h>

#include <cmath>
#include <limits>

namespace collidescope {
namespace {

thread_local PredicateCounters t_counters;

using filter::kAbsoluteBound;  // far above any underflow error in the filters
// Coordinates with magnitude in [2^-200, 2^200] are multiples of 2^-252, so a product of
// three differences is a multiple of 2^-756 and below 2^603: every expansion term is exact.
constexpr double kSafeMin = 0x1p-200;
constexpr double kSafeMax = 0x1p200;


constexpr int kUndecided = 2;  // a cheap stage's answer when it cannot decide

bool in_safe_range(double x) {
    const double m = std::fabs(x);
    return m == 0 || (m >= kSafeMin && m <= kSafeMax);
}

int sign_of(double x) { return (x > 0) - (x < 0); }

/// Sets `difference` to x - y rounded; true when that is exact. Exactness is read off the
/// two_diff error term, which is itself always exact.
bool exact_difference(double x, double y, double& difference) {
    double err;
    exact::two_diff(x, y, difference, err);
    return err == 0;
}

/// Sets `product` to x * y rounded; true when that is exact. Dekker's error term is exact
/// when x and y are differences of safe-range coordinates (multiples of 2^-252 below 2^201)
/// or products of two such, as here: nothing it computes can underflow or overflow.
bool exact_product(double x, double y, double& product) {
    double err;
    exact::two_product(x, y, product, err);
    return err == 0;
}

/// The orientation's exact sign without expansion arithmetic, or kUndecided. Two cheap exact
/// arguments, in order:
///  1. symbolic: a repeated point makes two rows of the determinant equal (or one zero), so
///     the determinant is exactly 0 (shared vertices, touching contact by position);
///  2. exact double evaluation: when every coordinate lies in the safe range and every
///     difference, 2x2 product, minor and scaled minor is exact in doubles (flat or
///     axis-aligned sheets, where zero differences make products exact; grid-snapped and
///     short-mantissa coordinates), the determinant is the sum of three exact doubles
///     t0 + t1 + t2. With s = t0 + t1 exact as well, the rounded s + t2 has the sign of the
///     exact sum (IEEE rounding is monotonic and fl(x + y) = 0 only when x + y = 0).
/// A term whose row-0 entry is zero is zero whatever its minor, so its minor is not needed.
[[gnu::noinline]] int orient3d_cheap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    if (a == d || b == d || c == d || a == b || a == c || b == c) return 0;
    const Vec3* points[4] = {&a, &b, &c, &d};
    for (const Vec3* p : points)
        if (!in_safe_range(p->x()) || !in_safe_range(p->y()) || !in_safe_range(p->z()))
            return kUndecided;
    double r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            if (!exact_difference((*points[i])[k], d[k], r[i][k])) return kUndecided;
    double t[3];
    for (int k = 0; k < 3; ++k) {  // cyclic cofactor expansion along row 0
        t[k] = 0;
        if (r[0][k] == 0) continue;
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        double p, q, minor;
        if (!exact_product(r[1][k1], r[2][k2], p) || !exact_product(r[1][k2], r[2][k1], q) ||
            !exact_difference(p, q, minor) || !exact_product(r[0][k], minor, t[k]))
            return kUndecided;
    }
    double s, err;
    exact::two_sum(t[0], t[1], s, err);
    if (err != 0) return kUndecided;
    return sign_of(s + t[2]);
}

/// True when the projections of a, b, c, d along `axis` (the other two coordinates) take at
/// most two distinct values: the four points then lie on one plane parallel to the axis
/// (through the line joining the two projected points, or any such plane when they coincide).
bool extruded_along_axis(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, int axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const auto same = [i, j](const Vec3& p, const Vec3& q) { return p[i] == q[i] && p[j] == q[j]; };
    const Vec3* second = nullptr;  // the first point whose projection differs from a's
    for (const Vec3* p : {&b, &c, &d}) {
        if (same(*p, a)) continue;
        if (second == nullptr) {
            second = p;
        } else if (!same(*p, *second)) {
            return false;
        }
    }
    return true;
}

/// orient2d's counterpart of orient3d_cheap: a repeated projected point gives 0; otherwise,
/// with exact differences and both products exact, the rounded difference of the products
/// has the exact sign.
[[gnu::noinline]] int orient2d_cheap(double ax, double ay, double bx, double by, double cx,
                                     double cy) {
    if ((ax == cx && ay == cy) || (bx == cx && by == cy) || (ax == bx && ay == by)) return 0;
    for (double x : {ax, ay, bx, by, cx, cy})
        if (!in_safe_range(x)) return kUndecided;
    double acx, acy, bcx, bcy, left, right;
    if (!exact_difference(ax, cx, acx) || !exact_difference(ay, cy, acy) ||
        !exact_difference(bx, cx, bcx) || !exact_difference(by, cy, bcy) ||
        !exact_product(acx, bcy, left) || !exact_product(acy, bcx, right))
        return kUndecided;
    return sign_of(left - right);
}

/// Exact sign of the 3x3 determinant of rows[i][k] - shift[k] (shift = 0 when null), with
/// GMP rationals: any finite doubles, no underflow or overflow possible.
int determinant3_sign_gmp(const double rows[3][3], const double* shift) {
    mpq_t det;
    mpq_init(det);
    determinant3_gmp(rows, shift, det);
    const int s = mpq_sgn(det);
    mpq_clear(det);
    return s;
}

/// The 3x3 determinant with rows (adx, ady, adz) etc. when every entry is an exact double:
/// each 2x2 minor is a 4-term expansion, each scaled minor 8 terms, the sum 24 terms.
int determinant3_sign_exact_entries(const double r[3][3]) {
    double terms[3][8];
    int counts[3];
    for (int k = 0; k < 3; ++k) {  // cyclic cofactor expansion along row 0
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        double p[2], q[2], minor[4];
        exact::two_product(r[1][k1], r[2][k2], p[1], p[0]);
        exact::two_product(r[1][k2], r[2][k1], q[1], q[0]);
        exact::negate(q, 2);
        const int n = exact::sum(p, 2, q, 2, minor);
        counts[k] = exact::scale(minor, n, r[0][k], terms[k]);
    }
    // Zeroed only to quiet GCC 12's maybe-uninitialized: sum() never reads past its count.
    double partial[16] = {}, total[24];
    const int n01 = exact::sum(terms[0], counts[0], terms[1], counts[1], partial);
    const int n = exact::sum(partial, n01, terms[2], counts[2], total);
    return exact::sign(total, n);
}

/// The same determinant when the entries are 2-term expansions e[i][k] (value e[..][0] +
/// e[..][1]): minors up to 16 terms, scaled minors 64, the sum 192.
int determinant3_sign_expansion_entries(const double e[3][3][2]) {
    double scratch[256], terms[3][64];
    int counts[3];
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        double p[8], q[8], minor[16];
        const int np = exact::product(e[1][k1], 2, e[2][k2], 2, p, scratch);
        const int nq = exact::product(e[1][k2], 2, e[2][k1], 2, q, scratch);
        exact::negate(q, nq);
        const int n = exact::sum(p, np, q, nq, minor);
        counts[k] = exact::product(minor, n, e[0][k], 2, terms[k], scratch);
    }
    double partial[128] = {}, total[192];  // zeroed as above
    const int n01 = exact::sum(terms[0], counts[0], terms[1], counts[1], partial);
    const int n = exact::sum(partial, n01, terms[2], counts[2], total);
    return exact::sign(total, n);
}

[[gnu::noinline]] int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    bool safe = true;
    for (const Vec3* p : {&a, &b, &c, &d})
        for (int k = 0; k < 3; ++k) safe = safe && in_safe_range((*p)[k]);
    const Vec3* rows[3] = {&a, &b, &c};
    if (!safe) {
        const double m[3][3] = {{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()},
                                {c.x(), c.y(), c.z()}};
        const double shift[3] = {d.x(), d.y(), d.z()};
        return determinant3_sign_gmp(m, shift);
    }
    // Differences as 2-term expansions; most inputs (float32 data) subtract exactly.
    double e[3][3][2];
    bool exact_differences = true;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            exact::two_diff((*rows[i])[k], d[k], e[i][k][1], e[i][k][0]);
            exact_differences = exact_differences && e[i][k][0] == 0;
        }
    if (exact_differences) {
        // A zero row or column (a point equal to d; all four points in an axis-aligned
        // plane, as flat cloth at rest) makes the determinant exactly zero.
        for (int i = 0; i < 3; ++i) {
            if (e[i][0][1] == 0 && e[i][1][1] == 0 && e[i][2][1] == 0) return 0;
            if (e[0][i][1] == 0 && e[1][i][1] == 0 && e[2][i][1] == 0) return 0;
        }
        double r[3][3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) r[i][k] = e[i][k][1];
        return determinant3_sign_exact_entries(r);
    }
    return determinant3_sign_expansion_entries(e);
}

[[gnu::noinline]] int orient2d_exact(double ax, double ay, double bx, double by, double cx,
                                     double cy) {
    const bool safe = in_safe_range(ax) && in_safe_range(ay) && in_safe_range(bx) &&
                      in_safe_range(by) && in_safe_range(cx) && in_safe_range(cy);
    if (!safe) {
        const double rows[3][3] = {{ax, ay, 1}, {bx, by, 1}, {cx, cy, 1}};
        return determinant3_sign_gmp(rows, nullptr);
    }
    double acx[2], acy[2], bcx[2], bcy[2];
    exact::two_diff(ax, cx, acx[1], acx[0]);
    exact::two_diff(ay, cy, acy[1], acy[0]);
    exact::two_diff(bx, cx, bcx[1], bcx[0]);
    exact::two_diff(by, cy, bcy[1], bcy[0]);
    double scratch[16], left[8], right[8], det[16];
    const int nl = exact::product(acx, 2, bcy, 2, left, scratch);
    const int nr = exact::product(acy, 2, bcx, 2, right, scratch);
    exact::negate(right, nr);
    return exact::sign(det, exact::sum(left, nl, right, nr, det));
}

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    // The filter (adjacent_filter.hpp, also inlined in the traversal); NaN or overflow leaves
    // it undecided and falls through to the exact path.
    if (const int filtered = filter::orient3d_filtered(a, b, c, d)) {
        ++t_counters.filtered;
        return filtered;
    }
    // Four points on one axis-aligned plane (a floor, a flat cloth at rest, sheets sliding on
    // one plane): a column of exact zeros (x - y == 0 only when x == y), so the determinant is
    // 0. The commonest exact zero on flat scenes, for nine comparisons.
    const auto zero_column = [&](int k) { return a[k] == d[k] && b[k] == d[k] && c[k] == d[k]; };
    if (zero_column(2) || zero_column(0) || zero_column(1)) {
        ++t_counters.shortcut;
        return 0;
    }
    // Four points over at most two points of an axis-aligned projection (an extrusion along
    // that axis: the side of a tube or prism meshed ring by ring, a wall): they lie on a plane
    // parallel to the axis, so the determinant is 0. Comparisons only.
    if (extruded_along_axis(a, b, c, d, 0) || extruded_along_axis(a, b, c, d, 1) ||
        extruded_along_axis(a, b, c, d, 2)) {
        ++t_counters.shortcut;
        return 0;
    }
    const int cheap = orient3d_cheap(a, b, c, d);
    if (cheap != kUndecided) {
        ++t_counters.shortcut;
        return cheap;
    }
    ++t_counters.exact;
    return orient3d_exact(a, b, c, d);
}

int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
    if (const int filtered = filter::orient2d_filtered(a, b, c, drop)) {
        ++t_counters.filtered;
        return filtered;
    }
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    // Three points on one axis-parallel line of the projection: a zero column, as in orient3d.
    if ((a[i] == c[i] && b[i] == c[i]) || (a[j] == c[j] && b[j] == c[j])) {
        ++t_counters.shortcut;
        return 0;
    }
    const int cheap = orient2d_cheap(a[i], a[j], b[i], b[j], c[i], c[j]);
    if (cheap != kUndecided) {
        ++t_counters.shortcut;
        return cheap;
    }
    ++t_counters.exact;
    return orient2d_exact(a[i], a[j], b[i], b[j], c[i], c[j]);
}

PredicateCounters predicate_counters() { return t_counters; }

}  // namespace collidescope
