#pragma once
// The exact narrow phase of the Embree + CGAL peer (bench/peers): what a user would assemble
// from CGAL 5.5 (libcgal-dev) behind a broad phase. Predicates only, from
// CGAL::Exact_predicates_inexact_constructions_kernel (floating-point filters, exact
// fallback): do_intersect on triangles, segments and points, orientation and collinearity
// tests. Implements DESIGN.md's definition on its own, not through the engine's code:
// degenerate triangles are the segment or point they are (CGAL's do_intersect requires
// non-degenerate triangles and segments), and within one object the self rule for triangles
// that share vertex indices (they collide only if their intersection holds a point outside
// the convex hull of the shared vertices).

#include "peers/peer_common.hpp"

#include <span>

namespace collidescope::peers {

/// Whether the candidate `pair` of `frame` collides (self rule when pair.obj_a == pair.obj_b).
bool cgal_pair_collides(const Frame& frame, const TrianglePair& pair);

/// The colliding pairs among `candidates` (each as often as it is a candidate), tested in
/// parallel on TBB's threads, as the engine's narrow phase runs: in no particular order.
PairSet cgal_narrow_phase(const Frame& frame, std::span<const TrianglePair> candidates);

}  // namespace collidescope::peers
