#pragma once
/// The trace interface: how the engine tells the outside world what each frame did.
///
/// The engine calls a TraceSink once per frame, on the engine's thread, after the frame's
/// pairs are final. The recorder implements it to write HDF5; `check` implements it to print
/// summaries and write pairs and stats. Sinks must not keep the spans past the call.

#include "collidescope/scene.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/types.hpp"

#include <span>

namespace collidescope {

/// What one finished frame hands to a sink.
struct FrameReport {
    const Frame& frame;                              ///< the frame's geometry
    const FrameStats& stats;                         ///< per-stage times and counts
    std::span<const TrianglePair> colliding_pairs;   ///< sorted, each pair once
};

/// Receives one report per frame.
class TraceSink {
public:
    virtual ~TraceSink() = default;
    virtual void on_frame(const FrameReport& report) = 0;
};

}  // namespace collidescope
