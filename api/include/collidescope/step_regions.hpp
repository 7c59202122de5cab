#pragma once
/// A step's interpenetration regions, as Session::regions() returns them
/// (SessionOptions::regions; docs/explanation/regions.md). Plain data: no engine types.

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace collidescope {

/// One intersection curve: points x y z, in order; a loop's last point joins its first.
struct StepCurve {
    bool closed = false;
    std::vector<std::array<double, 3>> points;
    double length = 0;
};

/// One region of one step: a connected set of colliding pairs of one object pair (obj_a ==
/// obj_b for self-contact), with an id that follows it over steps.
struct StepRegion {
    std::uint32_t id = 0;           ///< from 1, stable over steps
    std::uint32_t obj_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t pairs = 0;
    std::uint32_t triangles_a = 0;  ///< colliding triangles on obj_a's side
    std::uint32_t triangles_b = 0;  ///< on obj_b's (self: 0, all on a)
    std::uint32_t loops = 0;        ///< closed curves
    double curve_length = 0;
    double coplanar_area = 0;
    std::array<double, 3> box_min{};
    std::array<double, 3> box_max{};
    std::vector<StepCurve> curves;
    std::vector<std::uint32_t> predecessors;  ///< ids of the previous step's regions it continues, strongest first
    /// obj_a's surface area inside obj_b, obj_b's inside obj_a, and the penetration depth: NaN
    /// where not defined (the other object not closed; self-contact). docs/explanation/regions.md.
    double inside_area_a = std::numeric_limits<double>::quiet_NaN();
    double inside_area_b = std::numeric_limits<double>::quiet_NaN();
    double depth = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace collidescope
