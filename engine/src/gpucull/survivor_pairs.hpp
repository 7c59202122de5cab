#pragma once
// Mode 2's final step (engine/src/gpucull, private): candidate pairs among the triangles that
// survived the GPU cull, by sweep and prune over their closed boxes (the thesis builds a small
// hierarchy over the survivors, its rebuild cost R; over the few survivors a sorted sweep does
// the same job). Self-collision pairs within one object come from the same sweep over all of
// its triangles: the GPU cull is inter-object only.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope::gpucull {

/// Appends every (a, ta, b, tb), ta in `tris_a`, tb in `tris_b`, whose closed boxes overlap, in
/// canonical order (a < b). Returns the box tests made.
std::uint64_t survivor_pairs(const Frame& frame, std::uint32_t a, std::span<const std::uint32_t> tris_a,
                             std::uint32_t b, std::span<const std::uint32_t> tris_b,
                             std::vector<TrianglePair>& candidates);

/// Appends every (a, i, a, j), i < j, of object a whose closed boxes overlap. Returns the box
/// tests made.
std::uint64_t self_pairs(const Frame& frame, std::uint32_t a, std::vector<TrianglePair>& candidates);

}  // namespace collidescope::gpucull
