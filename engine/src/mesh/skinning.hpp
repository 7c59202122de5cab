#pragma once
// Linear blend skinning (engine/src/mesh, private).
//
// A vertex with influences (bone b_j, weight w_j), weights summing to 1, goes to
// sum_j w_j * (B_{b_j} * v), where B_b = (global transform of bone b's node) * (its offset
// matrix): computed as (sum_j w_j B_{b_j}) * v, the blended matrix applied once. Any number of
// influences per vertex. A vertex without influences goes to `fallback * v`.

#include "mesh/animated_model.hpp"

#include <span>

namespace collidescope::animation {

/// Influences in compressed rows: vertex v's are [begin[v], begin[v + 1]) of bone / weight.
struct Influences {
    std::span<const std::uint32_t> begin;  ///< size vertex count + 1
    std::span<const std::uint32_t> bone;   ///< indices into the bone matrices
    std::span<const double> weight;        ///< normalised per vertex
};

/// Skins `positions` into `out` (same size). Parallel over vertices (TBB); allocates nothing.
void skin(std::span<const Vec3> positions, const Influences& influences,
          std::span<const Affine> bone_matrices, const Affine& fallback, std::span<Vec3> out);

}  // namespace collidescope::animation
