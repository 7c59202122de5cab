#pragma once
// The regions layer of the overlay (replays/src, private): each frame's intersection curves as
// thick lines over the scene (drawn in screen space, so they stay visible at any zoom and
// through the meshes), each region labelled with its id; and the regions' lifetimes on the
// timeline. Only for recordings made with `record --regions`.

#include "frame_data.hpp"
#include "overlay.hpp"

#include "collidescope/replays/camera.hpp"

#include <cstdint>
#include <vector>

namespace collidescope::replays {

/// The colour of region `id` (cycling through a bright palette), RGB in [0, 1].
std::array<float, 3> region_colour(std::uint32_t id);

/// Draws `frame`'s curves and labels through `camera`, clipped to `scene` (ImGui, between its
/// NewFrame and Render: the caller's Overlay::draw).
void draw_region_curves(const FrameData& frame, const Camera& camera, const Rect& scene);

/// Draws the lifetimes as thin bars at the top of the timeline's plot (at, width, height in
/// pixels; `step` pixels per row), at most `lanes` bars above each other.
void draw_region_lives(const std::vector<RegionLife>& lives, float x, float y, float width, float height, float step,
                       int lanes = 6);

}  // namespace collidescope::replays
