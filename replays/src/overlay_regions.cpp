// The regions layer: curves and labels over the scene, lifetimes on the timeline.

#include "overlay_regions.hpp"
#include "overlay_colour.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace collidescope::replays {
std::array<float, 3> region_colour(std::uint32_t id) {
    // Bright against the grey meshes and the red colliding triangles.
    constexpr std::array<std::array<float, 3>, 6> k_palette = {{{1.00f, 0.92f, 0.10f},
                                                                {0.10f, 0.95f, 0.95f},
                                                                {0.95f, 0.35f, 0.95f},
                                                                {0.45f, 1.00f, 0.30f},
                                                                {1.00f, 0.60f, 0.10f},
                                                                {0.55f, 0.65f, 1.00f}}};
    return k_palette[(id == 0 ? 0 : id - 1) % k_palette.size()];
}

std::vector<RegionLife> region_lives(const recorder::Recording& recording, std::uint64_t rows) {
    std::vector<RegionLife> lives;
    if (!recording.has_regions()) return lives;
    for (std::uint64_t row = 0; row < rows; ++row) {
        for (const recorder::RecordedRegion& region : recording.regions(row, false)) {
            if (region.id > lives.size()) lives.resize(region.id);
            RegionLife& life = lives[region.id - 1];
            if (life.id == 0) life = {region.id, row, row};
            life.last = row;
        }
    }
    lives.erase(std::remove_if(lives.begin(), lives.end(), [](const RegionLife& l) { return l.id == 0; }), lives.end());
    return lives;
}

void draw_region_curves(const FrameData& frame, const Camera& camera, const Rect& scene) {
    if (frame.regions.empty()) return;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->PushClipRect(ImVec2(float(scene.x), float(scene.y)), ImVec2(float(scene.x + scene.w), float(scene.y + scene.h)));
    const float thickness = std::max(2.5f, float(scene.h) / 240.0f);
    std::vector<ImVec2> points;
    for (const recorder::RecordedRegion& region : frame.regions) {
        const ImU32 colour = colour32(region_colour(region.id));
        for (const recorder::RecordedRegion::Curve& curve : region.curves) {
            // A polyline per run of points in front of the camera.
            const auto flush = [&] {
                if (points.size() >= 2) {
                    draw->AddPolyline(points.data(), int(points.size()), colour,
                                      curve.closed && points.size() * 3 == curve.xyz.size() ? ImDrawFlags_Closed : 0,
                                      thickness);
                } else if (points.size() == 1) {
                    draw->AddCircleFilled(points[0], thickness, colour);
                }
                points.clear();
            };
            for (std::size_t p = 0; p + 2 < curve.xyz.size(); p += 3) {
                const std::array<double, 3> at = camera.project(curve.xyz[p], curve.xyz[p + 1], curve.xyz[p + 2]);
                if (at[2] < -1 || at[2] > 1) {
                    flush();
                    continue;
                }
                points.emplace_back(float(at[0]), float(at[1]));
            }
            flush();
        }
        // The label at the box's centre: "R3", with its depth where defined ("R3 0.21 deep"), on
        // a dark plate.
        const std::array<double, 3> centre =
            camera.project(0.5 * (region.box[0] + region.box[3]), 0.5 * (region.box[1] + region.box[4]),
                           0.5 * (region.box[2] + region.box[5]));
        if (centre[2] < -1 || centre[2] > 1) continue;
        char label[48];
        if (std::isnan(region.depth)) {
            std::snprintf(label, sizeof label, "R%u", region.id);
        } else {
            std::snprintf(label, sizeof label, "R%u %.3g deep", region.id, region.depth);
        }
        const ImVec2 size = ImGui::CalcTextSize(label);
        const ImVec2 at{static_cast<float>(centre[0]) + thickness * 2, static_cast<float>(centre[1]) - size.y - thickness * 2};
        draw->AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + size.x + 2, at.y + size.y + 1), IM_COL32(0, 0, 0, 200), 3.0f);
        draw->AddText(at, colour, label);
    }
    draw->PopClipRect();
}

void draw_region_lives(const std::vector<RegionLife>& lives, float x, float y, float width, float height, float step,
                       int lanes) {
    if (lives.empty() || lanes <= 0) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float bar = std::max(2.0f, std::min(4.0f, height / float(3 * lanes)));
    std::vector<std::uint64_t> lane_end(std::size_t(lanes), 0);
    std::vector<bool> lane_used(std::size_t(lanes), false);
    for (const RegionLife& life : lives) {
        // The first lane free at the region's first row (regions come in id order, so by start).
        int lane = -1;
        for (int k = 0; k < lanes && lane < 0; ++k) {
            if (!lane_used[std::size_t(k)] || lane_end[std::size_t(k)] < life.first) lane = k;
        }
        if (lane < 0) continue;  // more regions at once than lanes: the timeline shows the first ones
        lane_used[std::size_t(lane)] = true;
        lane_end[std::size_t(lane)] = life.last;
        const float top = y + float(lane) * (bar + 1);
        const float left = x + step * float(life.first);
        const float right = std::min(x + width, x + step * float(life.last + 1));
        draw->AddRectFilled(ImVec2(left, top), ImVec2(std::max(right - 1, left + 1), top + bar), colour32(region_colour(life.id)));
    }
}

}  // namespace collidescope::replays
