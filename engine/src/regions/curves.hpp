#pragma once
// Chaining a region's segments into curves (engine/src/regions, private).

#include "pair_intersection.hpp"

#include <span>
#include <vector>

namespace collidescope::regions {

/// The curves through the segments among `pieces` at `indices`: segments meet where their
/// ends' keys are equal. A key shared by exactly two segment ends joins them; a key held once
/// ends an open chain (a border, or an end the rounding left without a feature); a key held by
/// three or more ends (several curves through one vertex) ends every chain through it. Chains
/// that come back to their start are closed.
std::vector<IntersectionCurve> chain_curves(std::span<const Piece> pieces, std::span<const std::uint32_t> indices);

}  // namespace collidescope::regions
