#pragma once
// The overlay's colours as Dear ImGui takes them (replays/src, private).

#include <imgui.h>

#include <array>

namespace collidescope::replays {

/// An RGB colour (0-1 each) with `alpha`, packed as ImGui's 32-bit colour.
inline ImU32 colour32(const std::array<float, 3>& c, float alpha = 1.0f) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], alpha));
}

}  // namespace collidescope::replays
