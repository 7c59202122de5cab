#pragma once
// The brute-force culling (engine/src/brute, private), the `brute` method's and so the oracle's:
// for each object pair the object level hands it, every triangle pair (every i < j within one
// object under self-collision) through a closed per-triangle box prefilter. It must stay
// obviously correct; speed is the other algorithms' business. It keeps no state between
// frames. No narrow phase: the `brute` method (engine/src/methods) adds it.

#include "collidescope/frame_context.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/types.hpp"

#include <vector>

namespace collidescope::brute {

/// Every triangle pair of every object pair of `context` (and within each object when
/// context.self_collision) whose closed boxes overlap: canonical pairs, in an unspecified
/// order. Adds to counts.box_tests and counts.candidate_pairs; parallel (TBB) over the first
/// object's triangles.
std::vector<TrianglePair> brute_cull(const FrameContext& context, FrameStats& stats);

}  // namespace collidescope::brute
