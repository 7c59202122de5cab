#pragma once
// The between-frames marks of the overlay (replays/src, private; record --between-frames): on a
// moment-of-contact image, a ring around the first pair with its time; on the timeline, a tick
// between two frames wherever something passed through in that interval.

#include "frame_data.hpp"
#include "overlay.hpp"

#include "collidescope/replays/camera.hpp"

#include <cstdint>
#include <vector>

namespace collidescope::replays {

/// The colour of pass-throughs (the ring, the timeline's ticks), RGB in [0, 1].
std::array<float, 3> pass_through_colour();

/// On an image with FrameData::moment: a ring around the first pair's centre (screen space, so
/// it stays visible at any zoom) labelled "t = 0.8232", clipped to `scene` (ImGui, inside the
/// caller's Overlay::draw). Nothing on other frames.
void draw_contact_marker(const FrameData& frame, const Camera& camera, const Rect& scene);

/// A tick at the top of the timeline's plot between row r - 1 and row r for each r in `rows`
/// (at, height in pixels; `step` pixels per row).
void draw_pass_through_marks(const std::vector<std::uint64_t>& rows, float x, float y, float height, float step);

}  // namespace collidescope::replays
