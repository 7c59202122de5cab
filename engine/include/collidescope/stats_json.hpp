#pragma once
/// One frame's stats as the JSON object `check --stats` writes per line (engine/src/stats).
///
/// The one serializer of FrameStats: `check --stats` writes it, the embedding facade
/// (collidescope/session.hpp) and the Python module hand it out, so every consumer sees the
/// same names. Formatting only: no I/O.

#include "collidescope/stats.hpp"

#include <string>

namespace collidescope {

/// {"frame", "method", "ms": {every StageTimes field}, "counts": {every FrameCounts field}},
/// plus "gpu", "aabb", "hybrid" and "decision" objects when the frame's method filled them;
/// one line, no newline. NaN values are written as null.
std::string stats_json(const FrameStats& stats);

}  // namespace collidescope
