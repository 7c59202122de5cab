// The parameter of an edge's crossing with a plane: d_p / (d_p - d_q), with d the orientation
// determinant of the plane's corners and the end. The double evaluation carries Shewchuk's
// error bound on the same permanent; where the bounds exceed 1e-12 of |d_p| + |d_q| (the edge
// nearly in the plane), both determinants are evaluated exactly.

#include "edge_crossing.hpp"

#include "geometry/exact_determinant.hpp"

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
    const double rows[3][3] = {{plane[1].x(), plane[1].y(), plane[1].z()},
                               {plane[2].x(), plane[2].y(), plane[2].z()},
                               {point.x(), point.y(), point.z()}};
    const double shift[3] = {plane[0].x(), plane[0].y(), plane[0].z()};
    determinant3_gmp(rows, shift, out);
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
