// Inclusion-based root finding (after Wang et al. 2021, "Tight-Inclusion"): the times first,
// from the coplanarity cubic (solve), then boxes of
// (t, u, v) in order of their earliest time, each excluded when some coordinate of F is
// certainly non-zero over it, accepted when every coordinate's inclusion is within δ of 0,
// else split along the parameter that moves F the most.
//
// Rounding. The eight corner values are computed in double from the input coordinates; with M
// the largest magnitude of a coordinate (that axis, over every input point) and u = 2^-53, the
// differences X0 = p0 - a0 and the like are within 2Mu of exact, DX = X1 - X0 within 9Mu,
// X(t) = X0 + t DX within 20Mu (|X(t)| <= 6M), u Y(t) within 26Mu, and F = (X + uY) + vZ
// within 102Mu. The filter below uses 512 M u: five times that. A coordinate is excluded only
// when all eight values lie beyond it on one side, so a box that holds a zero is never
// excluded: no false negative. The box parameters are dyadic (halvings of [0, 1]), so t, u
// and v themselves are exact.

#include "ccd/inclusion.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace collidescope::ccd {
namespace {

// F(t, u, v) = X(t) + u Y(t) + v Z(t) with X(t) = x0 + t dx (and so on), per axis.
struct Function {
    Vec3 x0, dx, y0, dy, z0, dz;
    Vec3 x1, y1, z1;  ///< X, Y and Z at t = 1, as differences of the inputs (the coplanarity cubic's)
    Vec3 error;       ///< per axis: the bound on a value's rounding error, for t, u, v in [0, 1]
    double reach = 0;  ///< the largest magnitude of a coordinate of x0, x1, y0, y1, z0, z1
};

Function make_function(const Path& x_from, const Path& x_to, const Path& y_from, const Path& y_to, const Path& z_from,
                       const Path& z_to, double magnitude_scale, const Vec3& magnitude) {
    // X(t) = x_from(t) - x_to(t), likewise Y and Z: each a difference of two moving points.
    Function f;
    const Vec3 x0 = x_from[0] - x_to[0], x1 = x_from[1] - x_to[1];
    const Vec3 y0 = y_from[0] - y_to[0], y1 = y_from[1] - y_to[1];
    const Vec3 z0 = z_from[0] - z_to[0], z1 = z_from[1] - z_to[1];
    f.x0 = x0;
    f.dx = x1 - x0;
    f.y0 = y0;
    f.dy = y1 - y0;
    f.z0 = z0;
    f.dz = z1 - z0;
    f.x1 = x1;
    f.y1 = y1;
    f.z1 = z1;
    f.error = magnitude * magnitude_scale + Vec3::Constant(64 * std::numeric_limits<double>::denorm_min());
    for (const Vec3* d : {&x0, &x1, &y0, &y1, &z0, &z1}) f.reach = std::max(f.reach, d->cwiseAbs().maxCoeff());
    return f;
}

Vec3 largest_magnitude(std::initializer_list<const Path*> paths) {
    Vec3 m = Vec3::Zero();
    for (const Path* path : paths) m = m.cwiseMax(path->at(0).cwiseAbs()).cwiseMax(path->at(1).cwiseAbs());
    return m;
}

/// Fixed directions d along which d . F, multilinear too, also excludes boxes (F = 0 makes
/// every d . F = 0): n = Y x Z at the middle of a span of times (the face's normal, or the
/// normal of both edges), n x Z and n x Y. Near the time of contact n . F is the distance to
/// the contact plane whatever u and v are, and the other two are, within the plane, the
/// distances across the lines u = const and v = const: with the axes alone (which mix the
/// three) a box is excluded only once u and v are halved down to the features' gap.
/// Each d is scaled to a largest component of 1; d . F from the axes' values (each within
/// error_k) is within sum |d_k| error_k, plus the dot product's own rounding, far less than
/// that again (|F_k| <= 6 M_k, error_k = 512 M_k u): the bound used is twice the sum.
struct Directions {
    std::array<Vec3, 3> d{};
    std::array<double, 3> error{};
    int count = 0;
};

Directions directions_at(const Function& f, double t) {
    Directions out;
    const Vec3 y = f.y0 + t * f.dy, z = f.z0 + t * f.dz;
    const Vec3 n = y.cross(z);
    for (const Vec3& d : {n, n.cross(z), n.cross(y)}) {
        const double largest = d.cwiseAbs().maxCoeff();
        if (!(largest > 0 && std::isfinite(largest))) continue;  // Y and Z parallel: the axes alone
        out.d[out.count] = d / largest;
        out.error[out.count] = 2 * out.d[out.count].cwiseAbs().dot(f.error);
        ++out.count;
    }
    return out;
}

struct Box {
    double t0, t1, u0, u1, v0, v1;
    std::uint32_t level = 0;  ///< halvings from the whole domain
};

// Whether F(box.t0, u, v) is within δ of 0 at one (u, v) of the box and the domain: the
// least-squares zero of the affine F(t0, ., .), clamped into them. The value is computed as a
// corner's is (the same rounding bound holds for any u, v in [0, 1]), and u + v < 1 is
// decided exactly (a rounded sum below 1 is an exact sum below 1). A witness that no earlier
// box can beat: box.t0 is then the query's toi, as with an accepted box.
bool witness(const Function& f, bool simplex, const Box& box, double tolerance) {
    const Vec3 x = f.x0 + box.t0 * f.dx, y = f.y0 + box.t0 * f.dy, z = f.z0 + box.t0 * f.dz;
    const double yy = y.dot(y), yz = y.dot(z), zz = z.dot(z), xy = x.dot(y), xz = x.dot(z);
    const double det = yy * zz - yz * yz;
    double u = 0.5 * (box.u0 + box.u1), v = 0.5 * (box.v0 + box.v1);
    if (det > 0x1p-20 * (yy * zz) && std::isfinite(det)) {
        u = (yz * xz - zz * xy) / det;
        v = (yz * xy - yy * xz) / det;
        if (!std::isfinite(u) || !std::isfinite(v)) return false;
        u = std::clamp(u, box.u0, box.u1);
        v = std::clamp(v, box.v0, box.v1);
    } else {
        // Y and Z parallel, or within a thousandth of a radian: the least-squares zero is
        // ill-conditioned (the zeros, where there are any, lie along a line of (u, v)), and
        // clamping it lands on a corner far from them. Instead each parameter in turn is the
        // clamped least-squares one given the other, from the middle: for parallel edges two
        // rounds reach the nearest points of their parts in the box.
        for (int round = 0; round < 2; ++round) {
            if (zz > 0) v = std::clamp(-(xz + u * yz) / zz, box.v0, box.v1);
            if (yy > 0) u = std::clamp(-(xy + v * yz) / yy, box.u0, box.u1);
        }
        if (!std::isfinite(u) || !std::isfinite(v)) return false;
    }
    if (simplex && !(u + v < 1)) {
        const double scale = (1 - 0x1p-40) / (u + v);
        u = std::max(box.u0, u * scale);
        v = std::max(box.v0, v * scale);
        if (!(u + v < 1)) return false;
    }
    for (int k = 0; k < 3; ++k) {
        const double w = (x[k] + u * y[k]) + v * z[k];
        if (!(std::abs(w) + f.error[k] <= tolerance)) return false;
    }
    return true;
}

// Two doubles side by side (the box's two times), for the corners below.
using Pair = double __attribute__((vector_size(16)));

inline Pair pair_min(Pair a, Pair b) { return a < b ? a : b; }
inline Pair pair_max(Pair a, Pair b) { return a > b ? a : b; }

// Axis k of F at the box's eight corners (index bits: 1 t, 2 u, 4 v) into `values`; returns
// the least and the greatest. Both times at once: each value is (x + u y) + v z, rounded as
// the bound above assumes.
std::pair<double, double> corner_values(const Function& f, int k, const Box& box, double* values) {
    const Pair t{box.t0, box.t1};
    const Pair x = f.x0[k] + t * f.dx[k], y = f.y0[k] + t * f.dy[k], z = f.z0[k] + t * f.dz[k];
    const Pair w00 = (x + box.u0 * y) + box.v0 * z, w10 = (x + box.u1 * y) + box.v0 * z;
    const Pair w01 = (x + box.u0 * y) + box.v1 * z, w11 = (x + box.u1 * y) + box.v1 * z;
    std::memcpy(values, &w00, sizeof w00);
    std::memcpy(values + 2, &w10, sizeof w10);
    std::memcpy(values + 4, &w01, sizeof w01);
    std::memcpy(values + 6, &w11, sizeof w11);
    const Pair lo = pair_min(pair_min(w00, w10), pair_min(w01, w11));
    const Pair hi = pair_max(pair_max(w00, w10), pair_max(w01, w11));
    return {lo[0] < lo[1] ? lo[0] : lo[1], hi[0] > hi[1] ? hi[0] : hi[1]};
}

// Whether some axis of F is certainly non-zero over [ta, tb] x [0, 1]^2: the features apart
// along it for the whole span (their positions' ranges do not meet), the common case that a
// single box settles before the times are halved.
bool apart(const Function& f, double ta, double tb) {
    const Box whole{ta, tb, 0, 1, 0, 1};
    double values[8];
    for (int k = 0; k < 3; ++k) {
        const auto [lo, hi] = corner_values(f, k, whole, values);
        if (lo > f.error[k] || hi < -f.error[k]) return true;
    }
    return false;
}

// The boxes of [ta, tb] x the domain, earliest first; result.boxes counts over every span (the
// budget is the query's). Returns true once the query is decided: a contact (result set).
bool solve_span(const Function& f, bool simplex, const QueryConfig& config, double ta, double tb, QueryResult& result) {
    const Directions dirs = directions_at(f, 0.5 * (ta + tb));
    thread_local std::vector<Box> heap;
    heap.clear();
    // A min-heap on t0, the deeper box first among equal times (ties are common: u and v
    // halves share their t0), so a contact set wider than a point is descended into, not
    // spread over breadth-first.
    const auto later = [](const Box& a, const Box& b) { return a.t0 > b.t0 || (a.t0 == b.t0 && a.level < b.level); };
    heap.push_back({ta, tb, 0, 1, 0, 1, 0});
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Box box = heap.back();
        heap.pop_back();
        if (box.t0 > config.t_max) return false;  // every box left is later still
        if (simplex && box.u0 + box.v0 > 1) continue;
        if (++result.boxes > config.max_boxes) {
            // Give up conservatively: the earliest time not excluded (this box is the earliest).
            result.hit = true;
            result.toi = box.t0;
            result.resolved = false;
            return true;
        }
        // The eight corners, index bits: 1 t, 2 u, 4 v; one axis at a time, stopping at the
        // first axis that excludes the box.
        double value[3][8];
        bool excluded = false, within = true;
        for (int k = 0; k < 3 && !excluded; ++k) {
            const auto [lo, hi] = corner_values(f, k, box, value[k]);
            excluded = lo > f.error[k] || hi < -f.error[k];
            within = within && hi - lo + 2 * f.error[k] <= config.tolerance;
        }
        for (int i = 0; i < dirs.count && !excluded; ++i) {
            const Vec3& d = dirs.d[i];
            Pair lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi = -lo;
            for (int corner = 0; corner < 8; corner += 2) {
                Pair v[3];
                for (int k = 0; k < 3; ++k) std::memcpy(&v[k], &value[k][corner], sizeof v[k]);
                const Pair w = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
                lo = pair_min(lo, w);
                hi = pair_max(hi, w);
            }
            excluded = std::min(lo[0], lo[1]) > dirs.error[i] || std::max(hi[0], hi[1]) < -dirs.error[i];
        }
        if (excluded) continue;
        if (within || witness(f, simplex, box, config.tolerance)) {
            // Every value over the box is within δ of 0 (its earliest corner (t0, u0, v0) is in
            // the domain), or one value at t0 is; no earlier box holds a zero.
            result.hit = true;
            result.toi = box.t0;
            return true;
        }
        // Split the parameter along which F changes most over the box.
        std::array<double, 3> change{0, 0, 0};
        for (int corner = 0; corner < 8; ++corner) {
            for (int d = 0; d < 3; ++d) {
                if (corner & (1 << d)) continue;
                for (int k = 0; k < 3; ++k) change[d] = std::max(change[d], std::abs(value[k][corner | (1 << d)] - value[k][corner]));
            }
        }
        int d = static_cast<int>(std::max_element(change.begin(), change.end()) - change.begin());
        // Halve it where the midpoint lies strictly inside (near 1 a width of about 2^-53
        // cannot be halved in double); along no parameter (values flat to within the rounding
        // bound, wider than δ): a contact at this box's time, not proven within δ.
        const std::array<std::array<double, 2>, 3> range{{{box.t0, box.t1}, {box.u0, box.u1}, {box.v0, box.v1}}};
        const auto splits = [&](int k) {
            const double middle = 0.5 * (range[k][0] + range[k][1]);
            return range[k][0] < middle && middle < range[k][1];
        };
        if (!splits(d)) d = splits(0) ? 0 : splits(1) ? 1 : splits(2) ? 2 : -1;
        if (d < 0) {
            result.hit = true;
            result.toi = box.t0;
            result.resolved = false;
            return true;
        }
        Box low = box, high = box;
        low.level = high.level = box.level + 1;
        const double middle = 0.5 * (range[d][0] + range[d][1]);
        if (d == 0) low.t1 = high.t0 = middle;
        if (d == 1) low.u1 = high.u0 = middle;
        if (d == 2) low.v1 = high.v0 = middle;
        heap.push_back(low);
        std::push_heap(heap.begin(), heap.end(), later);
        heap.push_back(high);
        std::push_heap(heap.begin(), heap.end(), later);
    }
    return false;
}

// The determinant of X(t), Y(t) and Z(t) (each given at t = 0 and t = 1), a cubic in t: its
// four Bernstein coefficients on [0, 1], averages of determinants of the end vectors.
// `cross` holds y[j] x z[k] at index 2j + k (shared by every x against one pair y, z).
// Coefficient n on its own (the end ones, 0 and 3, need only cross[0] and cross[3]).
double coplanarity_at(const Path& x, const std::array<Vec3, 4>& cross, int n) {
    const auto det = [&](int i, int j, int k) { return x[i].dot(cross[2 * j + k]); };
    switch (n) {
        case 0: return det(0, 0, 0);
        case 1: return (det(1, 0, 0) + det(0, 1, 0) + det(0, 0, 1)) / 3;
        case 2: return (det(0, 1, 1) + det(1, 0, 1) + det(1, 1, 0)) / 3;
        default: return det(1, 1, 1);
    }
}

// All four.
std::array<double, 4> coplanarity(const Path& x, const std::array<Vec3, 4>& cross) {
    return {coplanarity_at(x, cross, 0), coplanarity_at(x, cross, 1), coplanarity_at(x, cross, 2),
            coplanarity_at(x, cross, 3)};
}

std::array<Vec3, 4> crosses(const Path& y, const Path& z) {
    return {y[0].cross(z[0]), y[0].cross(z[1]), y[1].cross(z[0]), y[1].cross(z[1])};
}

// The bound on those coefficients' rounding where X, Y and Z are correctly rounded differences
// of input coordinates: `largest` at least the magnitude of their coordinates (solve), or of
// the inputs' (MovingPlane: the differences are then at most twice it, within 500 largest^3 u).
double coplanarity_error(double largest) {
    // 256 subnormals: products that underflow, and up to 60 halvings of subnormal coefficients
    // (each average may round by half a subnormal, which the relative term does not cover there).
    return 4096 * largest * largest * largest * 0x1p-53 + 256 * std::numeric_limits<double>::denorm_min();
}

// The width of time spans handed to the boxes: F moves by at most δ/4 across one (all of
// [0, 1] for still features).
double box_width(const Function& f, double tolerance) {
    const double speed = (f.dx.cwiseAbs() + f.dy.cwiseAbs() + f.dz.cwiseAbs()).maxCoeff();
    return speed > 0 ? tolerance / (4 * speed) : 1;
}

// 2^k, exactly, for |k| < 1000, from its bits (std::ldexp is a library call, and the root
// cells asked for three of them a query).
double power_of_two(int k) { return std::bit_cast<double>(static_cast<std::uint64_t>(1023 + k) << 52); }

// The halvings that take a span wider than `width` down to it: ceil(log2(span / width)), or
// one more (the cells are then narrower, which is as good); 64 where the ratio overflows. The
// ratio exceeds 1 (the callers ask only once last_halving has said no), so it is normal and its
// exponent is read from its bits (std::ilogb is a library call).
int halvings_to(double span, double width) {
    const double ratio = span / width;
    if (!std::isfinite(ratio)) return 64;
    return static_cast<int>((std::bit_cast<std::uint64_t>(ratio) >> 52) & 0x7FF) - 1023 + 1;
}

// Whether a span goes to the boxes as it is: narrow enough, flat (halving would exclude
// nothing), as deep as the halvings go, or too narrow to halve in double.
bool last_halving(double a, double b, int depth, double width, bool flat) {
    const double middle = 0.5 * (a + b);
    return flat || b - a <= width || depth >= 60 || !(a < middle && middle < b);
}

// A polynomial's value at tau in [0, 1] from its Bernstein coefficients (de Casteljau's rule);
// for a dyadic tau, 1 - tau is exact, and each level of convex combinations (at most three)
// adds at most 3u times the largest coefficient to the value's error.
template <std::size_t N>
double bernstein_value(std::array<double, N> c, double tau) {
    const double u = 1 - tau;
    for (std::size_t level = 1; level < N; ++level) {
        for (std::size_t i = 0; i + level < N; ++i) c[i] = u * c[i] + tau * c[i + 1];
    }
    return c[0];
}

// The value and the derivative (in tau) at tau, both from de Casteljau's rule.
template <std::size_t N>
std::pair<double, double> bernstein_value_and_slope(std::array<double, N> c, double tau) {
    const double u = 1 - tau;
    for (std::size_t level = 1; level + 1 < N; ++level) {
        for (std::size_t i = 0; i + level < N; ++i) c[i] = u * c[i] + tau * c[i + 1];
    }
    return {u * c[0] + tau * c[1], static_cast<double>(N - 1) * (c[1] - c[0])};
}

// Where a span of a polynomial (the coplanarity cubic, or an orientation quadratic) holds
// exactly one root, the cell of the width halving would reach (2^-levels of the span) that holds
// the root, found at once instead of by `levels` halvings; nothing (-1) where that is not
// certain. Exactly one root: every coefficient lies beyond the bound and their signs change
// once (a polynomial has at most as many roots in a span as its Bernstein coefficients have sign
// changes, and as many modulo 2). The root is approximated in double (Newton's method, no
// guarantee needed), and its cell certified: the value at the cell's first time has the span's first
// sign and at its last time the span's last sign, each beyond the bound (plus the evaluation's
// own rounding). Then the rest of the span holds no root (an even number of roots on each side
// of the cell, out of exactly one). Returns the cell's index among the 2^levels.
template <std::size_t N>
double root_cell(const std::array<double, N>& c, double error, int levels) {
    double largest = 0;
    int changes = 0;
    for (std::size_t i = 0; i < N; ++i) {
        if (!(std::abs(c[i]) > error)) return -1;
        largest = std::max(largest, std::abs(c[i]));
        if (i > 0) changes += (c[i] > 0) != (c[i - 1] > 0);
    }
    if (changes != 1) return -1;
    // From the chord's root, Newton's steps (the derivative from the last level of de
    // Casteljau's rule), until a step moves less than a sixteenth of a cell.
    const double cells = power_of_two(levels), resolution = power_of_two(-levels - 4);
    double tau = c[0] / (c[0] - c[N - 1]);
    for (int step = 0; step < 8 && std::isfinite(tau); ++step) {
        const auto [value, slope] = bernstein_value_and_slope(c, tau);
        const double next = std::clamp(tau - value / slope, 0.0, 1.0);
        const bool settled = !(std::abs(next - tau) > resolution);
        tau = next;
        if (settled) break;
    }
    if (!std::isfinite(tau)) return -1;
    const double cell = std::min(std::floor(tau * cells), cells - 1);
    const double bound = error + 16 * 0x1p-53 * largest;
    const auto certain = [&](double at, double sign) {
        const double value = bernstein_value(c, at);
        return sign * value > bound;
    };
    if (cell > 0 && !certain(cell / cells, c[0] > 0 ? 1 : -1)) return -1;
    if (cell + 1 < cells && !certain((cell + 1) / cells, c[N - 1] > 0 ? 1 : -1)) return -1;
    return cell;
}

/// The four paths of an edge-edge query (p0, p1, q0, q1), for solve's flat case.
using Edges = std::array<const Path*, 4>;

// The solver. `simplex`: the domain is u + v <= 1 (vertex-face), else the unit square. `edges`:
// an edge-edge query's paths, searched by solve_flat_edges where the cubic is flat throughout.
//
// First the times: F = 0 needs X(t), Y(t) and Z(t) linearly dependent (X = -uY - vZ), so
// their determinant D(t), a cubic, must vanish. Its Bernstein coefficients on [0, 1] are
// averages of determinants of the inputs' differences X0 = x_from[0] - x_to[0] and the like,
// each correctly rounded (within u of itself, relative): with R the largest magnitude of a
// coordinate of the six, within 62 R^3 u of exact (six products of three, five sums), bounded
// here by 4096 R^3 u. R, not the coordinates' magnitude: small features far from the origin
// (cloth layers a gap apart, edges 0.008 long at coordinates near 1) had a bound 10^6 times
// their cubic's size, so nearly parallel edges a gap apart had a flat cubic and ran out of
// boxes.
// Spans of time are halved earliest first by de Casteljau's rule (each coefficient of a half
// an average of the whole's: the exact ones are the same averages of the exact ones, and each
// halving adds at most 3u times the largest coefficient; with at most 60 halvings, 512u times
// it covers them); a span whose coefficients all lie beyond the bound on one side holds no
// zero of D and no contact. A span goes to the boxes once it is narrow enough that F moves by
// at most δ/4 across it (so at its start a contact within it is within δ/4: a witness finds
// it at once), or once D is flat on it (every coefficient within four bounds of 0: moving in
// one plane, or nearly; halving it further would not exclude anything).
QueryResult solve_flat_edges(const Function& f, const Edges& edges, const QueryConfig& config);

QueryResult solve(const Function& f, bool simplex, const QueryConfig& config, const Edges* edges) {
    QueryResult result;
    const std::array<double, 4> whole = coplanarity({f.x0, f.x1}, crosses({f.y0, f.y1}, {f.z0, f.z1}));
    double size = 0;
    for (const double c : whole) size = std::max(size, std::abs(c));
    if (!std::isfinite(size)) return solve_span(f, simplex, config, 0, 1, result), result;
    const double error = coplanarity_error(f.reach) + 0x1p-44 * size;
    if (edges && size <= 4 * error) return solve_flat_edges(f, *edges, config);
    const double width = box_width(f, config.tolerance);
    struct Span {
        double a, b;
        std::array<double, 4> c;
        int depth;
    };
    // Each halving pops one span and pushes two, at most 60 deep: at most 61 spans wait.
    std::array<Span, 64> stack;
    int waiting = 0;
    stack[waiting++] = {0, 1, whole, 0};
    while (waiting > 0) {
        const Span s = stack[--waiting];
        if (s.a > config.t_max) break;  // the stack holds spans in time order: the rest is later
        const auto beyond = [&](double sign) {
            return sign * s.c[0] > error && sign * s.c[1] > error && sign * s.c[2] > error && sign * s.c[3] > error;
        };
        if (beyond(1) || beyond(-1)) continue;
        if (s.depth % 4 == 0 && apart(f, s.a, s.b)) continue;
        bool flat = true;
        for (const double c : s.c) flat = flat && std::abs(c) <= 4 * error;
        if (last_halving(s.a, s.b, s.depth, width, flat)) {
            if (solve_span(f, simplex, config, s.a, s.b, result)) return result;
            continue;
        }
        // The halvings down to the width, skipped where the span holds one certain root: its
        // cell's ends are dyadic (the span's are, and its depth plus the levels stays below
        // 53 bits), so they are exact.
        const int levels = halvings_to(s.b - s.a, width);
        if (levels >= 3 && s.depth + levels < 50) {
            const double cell = root_cell(s.c, error, levels);
            if (cell >= 0) {
                const double step = (s.b - s.a) * power_of_two(-levels);
                if (s.a + cell * step > config.t_max) break;  // the root, and every later span, too late
                if (solve_span(f, simplex, config, s.a + cell * step, s.a + (cell + 1) * step, result)) return result;
                continue;
            }
        }
        const double middle = 0.5 * (s.a + s.b);
        const double l1 = 0.5 * (s.c[0] + s.c[1]), m = 0.5 * (s.c[1] + s.c[2]), r2 = 0.5 * (s.c[2] + s.c[3]);
        const double l2 = 0.5 * (l1 + m), r1 = 0.5 * (m + r2), mid = 0.5 * (l2 + r1);
        stack[waiting++] = {middle, s.b, {mid, r1, r2, s.c[3]}, s.depth + 1};
        stack[waiting++] = {s.a, middle, {s.c[0], l1, l2, mid}, s.depth + 1};
    }
    return result;
}

constexpr double k_error_scale = 512 * 0x1p-53;

// ---- Motion in one plane ----------------------------------------------------------------
//
// Where every position lies in one plane, the coplanarity cubic is zero throughout and solve
// hands the whole interval to the boxes, which then search three parameters on a set of
// near-zeros as wide as the face. Projected along an axis the plane's normal is not
// perpendicular to (an affine bijection of the plane, so containment is kept), p(t) lies in
// the triangle only when the three orientations g_ab(t) = orient2d(a, b, p), g_bc and g_ca
// have no two strict opposite signs (all of one sign, or all zero on a flat triangle), and
// only when none is of the strict sign opposite to the area g_ab + g_bc + g_ca where that is
// non-zero. Each is a product of two linear functions, (b - a)(t) x (p - a)(t): a quadratic
// whose Bernstein coefficients on [0, 1] are e0 x w0, (e0 x w1 + e1 x w0) / 2 and e1 x w1 over
// the ends' differences. Each difference is correctly rounded (within u of itself, relative),
// so with D the largest magnitude of a computed projected difference, each product is within
// 3 D^2 u of exact, each cross product within 8 D^2 u and the middle coefficient within
// 20 D^2 u; the bound used is 64 D^2 u (it does not grow with the distance from the origin, as
// a bound on the coordinates would: at 10^6 times the features' size that one swamped the
// orientations and the queries ran out of boxes), plus 256 subnormals for products and
// halvings that underflow, plus 2^-44 times the largest coefficient for the de Casteljau
// halvings (as in solve). Where all three are within four bounds of zero on a span (the
// points on one line throughout, or nearly) halving would exclude nothing: the span goes to
// the boxes at once, as solve does with a flat cubic. Spans are halved earliest first and dropped where those signs rule
// contact out; a span narrow enough that F moves by at most δ/4 across it goes to the boxes.

using Quadratic = std::array<double, 3>;

// The bound on orientation quadratics' coefficients (above): `reach` the largest magnitude of a
// projected difference, `size` the largest coefficient (the halvings' share).
double orientation_error(double reach, double size) {
    return 64 * reach * reach * 0x1p-53 + 0x1p-44 * size + 256 * std::numeric_limits<double>::denorm_min();
}

// Whether every coefficient lies within four bounds of 0: halving would exclude nothing.
bool flat_quadratic(const Quadratic& q, double error) {
    return std::abs(q[0]) <= 4 * error && std::abs(q[1]) <= 4 * error && std::abs(q[2]) <= 4 * error;
}

// `reach` grows to the largest magnitude of a projected difference used.
Quadratic orientation(const Path& from, const Path& to, const Path& p, int i, int j, double& reach) {
    const auto cross = [&](const Vec3& e, const Vec3& w) { return e[i] * w[j] - e[j] * w[i]; };
    const Vec3 e0 = to[0] - from[0], e1 = to[1] - from[1];
    const Vec3 w0 = p[0] - from[0], w1 = p[1] - from[1];
    for (const Vec3* d : {&e0, &e1, &w0, &w1}) reach = std::max({reach, std::abs((*d)[i]), std::abs((*d)[j])});
    return {cross(e0, w0), 0.5 * (cross(e0, w1) + cross(e1, w0)), cross(e1, w1)};
}

// 1 or -1 when every coefficient lies beyond the bound on that side (the quadratic has that
// strict sign over the span), else 0.
int certain_sign(const Quadratic& q, double error) {
    if (q[0] > error && q[1] > error && q[2] > error) return 1;
    if (q[0] < -error && q[1] < -error && q[2] < -error) return -1;
    return 0;
}

// Whether the signs of the three orientations rule out p in the triangle over the span.
bool planar_excluded(const std::array<Quadratic, 3>& g, double error) {
    bool positive = false, negative = false;
    for (const Quadratic& q : g) {
        const int sign = certain_sign(q, error);
        positive = positive || sign > 0;
        negative = negative || sign < 0;
    }
    if (positive && negative) return true;
    // The area, the sum (three bounds, and the sums' rounding within the halving term).
    const Quadratic area{g[0][0] + g[1][0] + g[2][0], g[0][1] + g[1][1] + g[2][1], g[0][2] + g[1][2] + g[2][2]};
    const int sign = certain_sign(area, 4 * error);
    return (sign > 0 && negative) || (sign < 0 && positive);
}

std::pair<Quadratic, Quadratic> halves(const Quadratic& q) {
    const double l = 0.5 * (q[0] + q[1]), r = 0.5 * (q[1] + q[2]), mid = 0.5 * (l + r);
    return {{q[0], l, mid}, {mid, r, q[2]}};
}

QueryResult solve_in_plane(const Function& f, const std::array<Quadratic, 3>& whole, double error,
                           const QueryConfig& config) {
    QueryResult result;
    const double width = box_width(f, config.tolerance);
    struct Span {
        double a, b;
        std::array<Quadratic, 3> g;
        int depth;
    };
    std::array<Span, 64> stack;  // at most 61 wait, as in solve
    int waiting = 0;
    stack[waiting++] = {0, 1, whole, 0};
    while (waiting > 0) {
        const Span s = stack[--waiting];
        if (s.a > config.t_max) break;  // spans are popped in time order: the rest is later
        if (planar_excluded(s.g, error)) continue;
        const bool all_flat = std::all_of(s.g.begin(), s.g.end(), [&](const Quadratic& q) { return flat_quadratic(q, error); });
        if (last_halving(s.a, s.b, s.depth, width, all_flat)) {
            if (solve_span(f, true, config, s.a, s.b, result)) return result;
            continue;
        }
        // The vertex crossing one edge's line while it stays strictly on the inner side of the
        // other two: those two orientations of one certain sign, the third crossing zero once.
        // Entering (the third starts of the opposite sign), the contact starts at its root:
        // before it the signs conflict, after it all three agree (and so does the area, their
        // sum). Leaving, the vertex is inside at the span's start. Either way one cell of the
        // width halving holds the first contact, as in solve (dyadic ends, exact).
        const int levels = halvings_to(s.b - s.a, width);
        if (levels >= 3 && s.depth + levels < 50) {
            int crossing = -1, inner = 0, certain = 0;
            for (int k = 0; k < 3; ++k) {
                const int sign = certain_sign(s.g[k], error);
                if (sign == 0) crossing = k;
                certain += sign != 0;
                inner += sign;
            }
            if (certain == 2 && (inner == 2 || inner == -2)) {
                const Quadratic& q = s.g[crossing];
                const double cell = root_cell(q, error, levels);
                if (cell >= 0) {
                    const bool entering = (q[0] > 0) != (inner > 0);
                    const double step = (s.b - s.a) * power_of_two(-levels);
                    const double first = entering ? cell : 0;
                    if (solve_span(f, true, config, s.a + first * step, s.a + (first + 1) * step, result)) return result;
                    if (entering) continue;  // only past t_max; leaving, the same (else halved)
                }
            }
        }
        const double middle = 0.5 * (s.a + s.b);
        Span early{s.a, middle, {}, s.depth + 1}, late{middle, s.b, {}, s.depth + 1};
        for (int k = 0; k < 3; ++k) std::tie(early.g[k], late.g[k]) = halves(s.g[k]);
        stack[waiting++] = late;
        stack[waiting++] = early;
    }
    return result;
}

// ---- Edges on a flat cubic --------------------------------------------------------------
//
// Where the coplanarity cubic is flat over the whole interval (every coefficient within four
// bounds of 0: the edges move in one plane, or stay parallel, or nearly), solve cannot take
// the times from it, and the boxes alone would search (t, u, v) along a set of near-zeros as
// long as the edges: sliding parallel edges a gap apart, or passing through each other's line,
// ran a query out of boxes (contact-rods: the rings of neighbouring tubes, in one horizontal
// plane). A contact puts a point of each edge on the other's line: with e = p1 - p0,
// e x (q(v) - p0) = 0 for some v in [0, 1], affine in v, so on no axis k are the components
// e x (q0 - p0) and e x (q1 - p0) of one strict sign; likewise with the edges exchanged. Each
// component is an orientation quadratic of the planar query (its projection dropping axis k),
// under the same rounding bound. Spans are halved earliest first and dropped where some axis
// puts both ends of one edge strictly on one side of the other's line (for edges in one plane,
// the test of two segments crossing); a span that is narrow enough, or flat on every side
// (collinear edges, or nearly), goes to the boxes, as in solve.

// [3 * line + axis][end]: line 0 is p's (ends q0, q1), line 1 is q's (ends p0, p1).
using LineSides = std::array<std::array<Quadratic, 2>, 6>;

bool sides_exclude(const LineSides& g, double error) {
    for (const auto& ends : g) {
        const int sign = certain_sign(ends[0], error);
        if (sign != 0 && sign == certain_sign(ends[1], error)) return true;
    }
    return false;
}

QueryResult solve_flat_edges(const Function& f, const Edges& edges, const QueryConfig& config) {
    const auto& [p0, p1, q0, q1] = edges;
    LineSides whole;
    double reach = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        whole[k] = {orientation(*p0, *p1, *q0, i, j, reach), orientation(*p0, *p1, *q1, i, j, reach)};
        whole[3 + k] = {orientation(*q0, *q1, *p0, i, j, reach), orientation(*q0, *q1, *p1, i, j, reach)};
    }
    double size = 0;
    for (const auto& ends : whole) {
        for (const Quadratic& q : ends) size = std::max({size, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
    }
    QueryResult result;
    const double error = orientation_error(reach, size);
    if (!std::isfinite(error)) return solve_span(f, false, config, 0, 1, result), result;
    const double width = box_width(f, config.tolerance);
    struct Span {
        double a, b;
        LineSides g;
        int depth;
    };
    std::array<Span, 64> stack;  // at most 61 wait, as in solve
    int waiting = 0;
    stack[waiting++] = {0, 1, whole, 0};
    while (waiting > 0) {
        const Span s = stack[--waiting];
        if (s.a > config.t_max) break;  // spans are popped in time order: the rest is later
        if (sides_exclude(s.g, error)) continue;
        bool all_flat = true;
        for (const auto& ends : s.g) all_flat = all_flat && flat_quadratic(ends[0], error) && flat_quadratic(ends[1], error);
        if (last_halving(s.a, s.b, s.depth, width, all_flat)) {
            if (solve_span(f, false, config, s.a, s.b, result)) return result;
            continue;
        }
        const double middle = 0.5 * (s.a + s.b);
        Span early{s.a, middle, {}, s.depth + 1}, late{middle, s.b, {}, s.depth + 1};
        for (std::size_t k = 0; k < s.g.size(); ++k) {
            for (int end = 0; end < 2; ++end) std::tie(early.g[k][end], late.g[k][end]) = halves(s.g[k][end]);
        }
        stack[waiting++] = late;
        stack[waiting++] = early;
    }
    return result;
}

}  // namespace

MovingPlane::MovingPlane(const Path& a, const Path& b, const Path& c, double largest)
    : m_origin(a), m_y{b[0] - a[0], b[1] - a[1]}, m_z{c[0] - a[0], c[1] - a[1]},
      m_crosses{m_y[0].cross(m_z[0]), Vec3::Zero(), Vec3::Zero(), m_y[1].cross(m_z[1])},
      m_error(coplanarity_error(largest)) {}

int MovingPlane::side(const Path& p) {
    // coplanarity's coefficients: the ends', then the inner.
    const Path x{p[0] - m_origin[0], p[1] - m_origin[1]};
    const double first = coplanarity_at(x, m_crosses, 0);
    const int sign = first > m_error ? 1 : first < -m_error ? -1 : 0;
    if (sign == 0 || !(sign * coplanarity_at(x, m_crosses, 3) > m_error)) return 0;
    if (!m_mixed) {
        m_crosses[1] = m_y[0].cross(m_z[1]);
        m_crosses[2] = m_y[1].cross(m_z[0]);
        m_mixed = true;
    }
    const bool inner = sign * coplanarity_at(x, m_crosses, 1) > m_error && sign * coplanarity_at(x, m_crosses, 2) > m_error;
    return inner ? sign : 0;
}

QueryResult vertex_face(const Path& p, const Path& a, const Path& b, const Path& c, const QueryConfig& config) {
    // F = (p - a) + u (a - b) + v (a - c).
    const Vec3 magnitude = largest_magnitude({&p, &a, &b, &c});
    return solve(make_function(p, a, a, b, a, c, k_error_scale, magnitude), true, config, nullptr);
}

QueryResult vertex_face_in_plane(const Path& p, const Path& a, const Path& b, const Path& c, int drop,
                                 const QueryConfig& config) {
    const Vec3 magnitude = largest_magnitude({&p, &a, &b, &c});
    const Function f = make_function(p, a, a, b, a, c, k_error_scale, magnitude);
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    double reach = 0;
    const std::array<Quadratic, 3> g{orientation(a, b, p, i, j, reach), orientation(b, c, p, i, j, reach),
                                     orientation(c, a, p, i, j, reach)};
    double size = 0;
    for (const Quadratic& q : g) size = std::max({size, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
    const double error = orientation_error(reach, size);
    if (!std::isfinite(error)) return solve(f, true, config, nullptr);
    return solve_in_plane(f, g, error, config);
}

QueryResult edge_edge(const Path& p0, const Path& p1, const Path& q0, const Path& q1, const QueryConfig& config) {
    // F = (p0 - q0) + u (p1 - p0) + v (q0 - q1).
    const Vec3 magnitude = largest_magnitude({&p0, &p1, &q0, &q1});
    const Edges edges{&p0, &p1, &q0, &q1};
    return solve(make_function(p0, q0, p1, p0, q0, q1, k_error_scale, magnitude), false, config, &edges);
}

}  // namespace collidescope::ccd
