#pragma once
// The narrow phase: the exact triangle-triangle test on candidate pairs (engine/src/stages,
// private; DESIGN.md "The engine, per frame", step 4). Every method ends with it.

#include "collidescope/scene.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/types.hpp"

#include <span>
#include <vector>

namespace collidescope {

/// Tests every candidate exactly, in parallel (TBB): triangles_intersect between objects,
/// self_triangles_collide (with the file's vertex indices) within one. Appends the colliding
/// ones to `colliding` (in an unspecified order) and sets ms.narrow, counts.exact_tests,
/// counts.exact_fallbacks (predicate calls that needed the exact fallback, expansions or
/// GMP: neither the float filter nor the cheap exact stage decided them; summed over threads),
/// counts.exact_shortcuts (calls the cheap exact stage decided) and counts.colliding_pairs (what it appended). Candidates are canonical pairs.
void narrow_phase(const Frame& frame, std::span<const TrianglePair> candidates,
                  std::vector<TrianglePair>& colliding, FrameStats& stats);

/// The exact test of one pair of the frame (either kind), as narrow_phase runs it.
bool pair_collides(const Frame& frame, const TrianglePair& pair);

}  // namespace collidescope
