#pragma once
// What an interval needs of its two frames (engine/src/ccd, private), shared by the detector
// and the reference.

#include "collidescope/scene.hpp"

namespace collidescope::ccd {

/// Throws InputError unless `to` has `from`'s objects with the same triangles and every
/// coordinate of both is finite and at most 1e100 in size; the message names the frame, the
/// object and the vertex. Returns the interval's tolerance: `requested_tolerance` when
/// positive, else 1e-6 times the largest extent of the box of both frames' vertices (a scene
/// of one point: 1e-6).
double check_interval(const Frame& from, const Frame& to, double requested_tolerance);

/// The tolerance alone, as check_interval returns it (for a peer that takes ours).
double interval_tolerance(const Frame& from, const Frame& to, double requested);

}  // namespace collidescope::ccd
