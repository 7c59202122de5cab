// Inclusion-based root finding (after Wang et al. 2021, "Tight-Inclusion"): boxes of
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
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

namespace collidescope::ccd {
namespace {

// F(t, u, v) = X(t) + u Y(t) + v Z(t) with X(t) = x0 + t dx (and so on), per axis.
struct Function {
    Vec3 x0, dx, y0, dy, z0, dz;
    Vec3 x1, y1, z1;  ///< X, Y and Z at t = 1, as differences of the inputs (the coplanarity filter's)
    Vec3 error;  ///< per axis: the bound on a corner value's rounding error
    /// A fixed direction n (Y x Z halfway through the interval: the face's normal, or the
    /// normal of both edges) along which n . F, multilinear too, also excludes boxes: where n
    /// is the normal of the plane where contact happens, a box of times before contact is
    /// excluded by it whatever its u and v, so the search descends in time without halving u
    /// and v (which axis-aligned coordinates mixing normal and tangent parts would need).
    /// Zero when Y and Z are parallel halfway.
    Vec3 normal = Vec3::Zero();
    double normal_error = 0;  ///< the bound on n . F's rounding: 2 sum |n_k| error_k
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
    const Vec3 normal = (f.y0 + 0.5 * f.dy).cross(f.z0 + 0.5 * f.dz);
    const double largest = normal.cwiseAbs().maxCoeff();
    if (largest > 0 && std::isfinite(largest)) {
        f.normal = normal / largest;
        // n . F from the axes' values (each within error_k): sum |n_k| error_k, plus the dot
        // product's own rounding, far less than that again (|F_k| <= 6 M_k, error_k = 512 M_k u).
        f.normal_error = 2 * f.normal.cwiseAbs().dot(f.error);
    }
    return f;
}

Vec3 largest_magnitude(std::initializer_list<const Path*> paths) {
    Vec3 m = Vec3::Zero();
    for (const Path* path : paths) m = m.cwiseMax(path->at(0).cwiseAbs()).cwiseMax(path->at(1).cwiseAbs());
    return m;
}

struct Box {
    double t0, t1, u0, u1, v0, v1;
    std::uint32_t level = 0;  ///< halvings from the whole domain
};

// Whether X(t), Y(t) and Z(t) can be linearly dependent for some t in [0, 1], which a zero of
// F needs (X = -uY - vZ): their determinant is a cubic in t, and when its four Bernstein
// coefficients on [0, 1] share a strict sign, so does the cubic (it is their weighted mean).
// Each determinant is of differences of input coordinates (at most 2M in size, 2Mu off); the
// coefficients are within 480 M^3 u of exact (six products of three, five sums), bounded here
// by 4096 M^3 u.
bool may_be_coplanar(const Function& f, double largest) {
    const Vec3 x[2] = {f.x0, f.x1}, y[2] = {f.y0, f.y1}, z[2] = {f.z0, f.z1};
    const auto det = [&](int i, int j, int k) { return x[i].dot(y[j].cross(z[k])); };
    const double b[4] = {det(0, 0, 0), (det(1, 0, 0) + det(0, 1, 0) + det(0, 0, 1)) / 3,
                         (det(0, 1, 1) + det(1, 0, 1) + det(1, 1, 0)) / 3, det(1, 1, 1)};
    const double error = 4096 * largest * largest * largest * 0x1p-53 + 64 * std::numeric_limits<double>::denorm_min();
    const bool positive = b[0] > error && b[1] > error && b[2] > error && b[3] > error;
    const bool negative = b[0] < -error && b[1] < -error && b[2] < -error && b[3] < -error;
    return !positive && !negative;
}

// The solver. `simplex`: the domain is u + v <= 1 (vertex-face), else the unit square.
QueryResult solve(const Function& f, bool simplex, const QueryConfig& config) {
    QueryResult result;
    thread_local std::vector<Box> heap;
    heap.clear();
    // A min-heap on t0, the deeper box first among equal times (ties are common: u and v
    // halves share their t0), so a contact set wider than a point is descended into, not
    // spread over breadth-first.
    const auto later = [](const Box& a, const Box& b) { return a.t0 > b.t0 || (a.t0 == b.t0 && a.level < b.level); };
    heap.push_back({0, 1, 0, 1, 0, 1, 0});
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Box box = heap.back();
        heap.pop_back();
        if (box.t0 > config.t_max) break;  // every box left is later still
        if (simplex && box.u0 + box.v0 > 1) continue;
        if (++result.boxes > config.max_boxes) {
            // Give up conservatively: the earliest time not excluded (this box is the earliest).
            result.hit = true;
            result.toi = box.t0;
            result.resolved = false;
            return result;
        }
        // The eight corners, index bits: 1 t, 2 u, 4 v; one axis at a time, stopping at the
        // first axis that excludes the box.
        double value[3][8];
        bool excluded = false, within = true;
        for (int k = 0; k < 3 && !excluded; ++k) {
            const double x[2] = {f.x0[k] + box.t0 * f.dx[k], f.x0[k] + box.t1 * f.dx[k]};
            const double y[2] = {f.y0[k] + box.t0 * f.dy[k], f.y0[k] + box.t1 * f.dy[k]};
            const double z[2] = {f.z0[k] + box.t0 * f.dz[k], f.z0[k] + box.t1 * f.dz[k]};
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (int corner = 0; corner < 8; ++corner) {
                const int t = corner & 1;
                const double u = corner & 2 ? box.u1 : box.u0;
                const double v = corner & 4 ? box.v1 : box.v0;
                const double w = (x[t] + u * y[t]) + v * z[t];
                value[k][corner] = w;
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
            excluded = lo > f.error[k] || hi < -f.error[k];
            within = within && hi - lo + 2 * f.error[k] <= config.tolerance;
        }
        if (!excluded && f.normal_error > 0) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (int corner = 0; corner < 8; ++corner) {
                const double w = f.normal[0] * value[0][corner] + f.normal[1] * value[1][corner] + f.normal[2] * value[2][corner];
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
            excluded = lo > f.normal_error || hi < -f.normal_error;
        }
        if (excluded) continue;
        if (within) {
            // Every value over the box is within δ of 0, the box's earliest corner (t0, u0,
            // v0) is in the domain, and no earlier box holds a zero.
            result.hit = true;
            result.toi = box.t0;
            return result;
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
            return result;
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
    return result;
}

constexpr double k_error_scale = 512 * 0x1p-53;

}  // namespace

QueryResult vertex_face(const Path& p, const Path& a, const Path& b, const Path& c, const QueryConfig& config) {
    // F = (p - a) + u (a - b) + v (a - c).
    const Vec3 magnitude = largest_magnitude({&p, &a, &b, &c});
    const Function f = make_function(p, a, a, b, a, c, k_error_scale, magnitude);
    if (!may_be_coplanar(f, magnitude.maxCoeff())) return {};
    return solve(f, true, config);
}

QueryResult edge_edge(const Path& p0, const Path& p1, const Path& q0, const Path& q1, const QueryConfig& config) {
    // F = (p0 - q0) + u (p1 - p0) + v (q0 - q1).
    const Vec3 magnitude = largest_magnitude({&p0, &p1, &q0, &q1});
    const Function f = make_function(p0, q0, p1, p0, q0, q1, k_error_scale, magnitude);
    if (!may_be_coplanar(f, magnitude.maxCoeff())) return {};
    return solve(f, false, config);
}

}  // namespace collidescope::ccd
