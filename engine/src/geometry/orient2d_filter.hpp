#pragma once
/// orient2d's floating-point filter, inline for loops that take millions of signs a frame
/// (bvh refit's projected orientations). collidescope::orient2d runs the same filter first.

#include "collidescope/types.hpp"

#include <cmath>
#include <limits>

namespace collidescope::filter {

/// Shewchuk's ccwerrboundA is (3 + 16 eps) eps; 4 eps plus an absolute term that covers
/// gradual underflow in the products (predicates.cpp).
inline constexpr double kOrient2dBound = 4.0 * (std::numeric_limits<double>::epsilon() / 2);
inline constexpr double kAbsoluteBound = 0x1p-960;

/// The sign of orient2d(a, b, c, drop) when the filter certifies it (+1 or -1), else 0
/// (undecided: the exact predicate must answer).
inline int orient2d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const double detleft = (a[i] - c[i]) * (b[j] - c[j]);
    const double detright = (a[j] - c[j]) * (b[i] - c[i]);
    const double det = detleft - detright;
    const double permanent = std::fabs(detleft) + std::fabs(detright);
    const double bound = kOrient2dBound * permanent + kAbsoluteBound;
    if (!(permanent < std::numeric_limits<double>::max())) return 0;
    return (det > bound) - (-det > bound);
}

}  // namespace collidescope::filter
