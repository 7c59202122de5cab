#pragma once
// Morph targets (engine/src/mesh, private): v = base + sum_i w_i (target_i - base).

#include "collidescope/types.hpp"

#include <span>
#include <vector>

namespace collidescope::animation {

/// out[v] = base[v] + sum_i weights[i] * (targets[i][v] - base[v]) over the targets with a
/// non-zero weight (weights.size() <= targets.size(); every target as long as base; out too).
/// Parallel over vertices (TBB); allocates nothing.
void apply_morph(std::span<const Vec3> base, std::span<const std::vector<Vec3>> targets,
                 std::span<const double> weights, std::span<Vec3> out);

}  // namespace collidescope::animation
