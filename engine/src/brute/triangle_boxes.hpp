#pragma once
// Closed axis-aligned boxes of single triangles, the brute method's prefilter
// (engine/src/brute, private).

#include "collidescope/scene.hpp"

#include <array>
#include <vector>

namespace collidescope {

/// The box of one triangle: per axis, the minimum and maximum of its corners' coordinates.
/// Built with comparisons only, so its faces lie exactly on input coordinates.
struct TriangleBox {
    std::array<double, 3> lo;
    std::array<double, 3> hi;
};

/// True when the closed boxes share a point: touching boxes overlap (touching triangles
/// collide, so the prefilter must keep them).
inline bool boxes_overlap(const TriangleBox& a, const TriangleBox& b) {
    return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] &&  //
           a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&  //
           a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}

/// The boxes of every triangle of `object`, in triangle order.
std::vector<TriangleBox> triangle_boxes(const ObjectFrame& object);

}  // namespace collidescope
