// The parameter of an edge's crossing with a plane: d_p / (d_p - d_q), with d the orientation
// determinant of the plane's corners and the end. The double evaluation carries Shewchuk's
// error bound on the same permanent; where the bounds exceed 1e-12 of |d_p| + |d_q| (the edge
// nearly in the plane), both determinants are evaluated exactly.

#include "edge_crossing.hpp"

#include <Eigen/Geometry>
#include <gmp.h>

#include <algorithm>
#include <cmath>

namespace collidescope::regions {
namespace {

struct Determinant {
    double value;
    double bound;  ///< |value - exact| <= bound
};

Determinant determinant(const std::array<Vec3, 3>& plane, const Vec3& point) {
    const Vec3 u = plane[1] - plane[0], v = plane[2] - plane[0], w = point - plane[0];
    const Vec3 n = u.cross(v);
    double permanent = 0;
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        permanent += (std::abs(u[k1] * v[k2]) + std::abs(u[k2] * v[k1])) * std::abs(w[k]);
    }
    // Shewchuk's errboundA for orient3d is (7 + 56 eps) eps; rounded up.
    return {n.dot(w), 8e-16 * permanent};
}

// The exact determinant of (plane, point) as a rational.
void exact_determinant(const std::array<Vec3, 3>& plane, const Vec3& point, mpq_t out) {
    mpq_t m[3][3], t0, t1;
    mpq_inits(t0, t1, nullptr);
    const Vec3* rows[3] = {&plane[1], &plane[2], &point};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            mpq_init(m[i][k]);
            mpq_set_d(m[i][k], (*rows[i])[k]);
            mpq_set_d(t0, plane[0][k]);
            mpq_sub(m[i][k], m[i][k], t0);
        }
    }
    mpq_set_ui(out, 0, 1);
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        mpq_mul(t0, m[0][k1], m[1][k2]);
        mpq_mul(t1, m[0][k2], m[1][k1]);
        mpq_sub(t0, t0, t1);
        mpq_mul(t0, t0, m[2][k]);
        mpq_add(out, out, t0);
    }
    for (auto& row : m) {
        for (auto& cell : row) mpq_clear(cell);
    }
    mpq_clears(t0, t1, nullptr);
}

}  // namespace

double crossing_parameter(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& plane) {
    const Determinant dp = determinant(plane, p), dq = determinant(plane, q);
    const double spread = std::abs(dp.value) + std::abs(dq.value);
    if (dp.bound + dq.bound <= 1e-12 * spread && dp.value * dq.value < 0) {
        return std::clamp(dp.value / (dp.value - dq.value), 0.0, 1.0);
    }
    mpq_t ep, eq, s;
    mpq_inits(ep, eq, s, nullptr);
    exact_determinant(plane, p, ep);
    exact_determinant(plane, q, eq);
    mpq_sub(s, ep, eq);
    double result = 0.5;
    if (mpq_sgn(s) != 0) {
        mpq_div(s, ep, s);
        result = std::clamp(mpq_get_d(s), 0.0, 1.0);
    }
    mpq_clears(ep, eq, s, nullptr);
    return result;
}

}  // namespace collidescope::regions
