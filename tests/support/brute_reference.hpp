#pragma once
/// The slowest, most obvious definition of a frame's colliding pairs: every triangle pair of
/// every object pair, and every pair within each object under self-collision; no prefilter,
/// no object level, no threads. The brute method (and through it every method) is tested
/// against this.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <iosfwd>
#include <vector>

namespace collidescope::testing {

/// The colliding pairs of `frame`, canonical and sorted.
std::vector<TrianglePair> reference_colliding_pairs(const Frame& frame, bool self_collision);

}  // namespace collidescope::testing

namespace collidescope {

/// Prints a pair as "(objA,triA | objB,triB)" in GoogleTest messages.
void PrintTo(const TrianglePair& pair, std::ostream* out);

}  // namespace collidescope
