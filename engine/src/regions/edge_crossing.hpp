#pragma once
// Where an edge crosses a plane (engine/src/regions, private), accurate even when the edge
// and the plane are nearly parallel.

#include "collidescope/types.hpp"

#include <array>

namespace collidescope::regions {

/// The parameter s in [0, 1] of the point p + s (q - p) where the segment (p, q), whose ends
/// lie strictly on opposite sides of the plane through `plane` (as orient3d decides), crosses
/// that plane. Computed in double from the two ends' determinants when their error bounds are
/// small against them; otherwise from the exact determinants (GMP rationals), so a crossing of
/// two nearly coplanar triangles lands where it is, not where the rounding of a normal put it.
double crossing_parameter(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& plane);

}  // namespace collidescope::regions
