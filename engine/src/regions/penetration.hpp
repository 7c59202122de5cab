#pragma once
// How far two objects go into each other, per region (engine/src/regions, private): the area
// of each side's surface inside the other object and the penetration depth, where the other
// object is closed. docs/explanation/regions.md says what is computed and how exactly.

#include "pair_intersection.hpp"

#include <span>

namespace collidescope::regions {

/// Sets depth, inside_area_a and inside_area_b of `regions` (find_regions' regions of `pairs`,
/// whose intersections are `pieces`). Self-contact regions keep them undefined (NaN).
void measure_penetration(const Frame& frame, std::span<const TrianglePair> pairs, std::span<const Piece> pieces,
                         std::span<Region> regions);

}  // namespace collidescope::regions
