// The between-frames marks: the moment-of-contact ring, the timeline's pass-through ticks.

#include "overlay_moment.hpp"
#include "overlay_colour.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace collidescope::replays {

std::array<float, 3> pass_through_colour() { return {1.0f, 0.25f, 0.85f}; }  // magenta: apart from red and the regions

void draw_contact_marker(const FrameData& frame, const Camera& camera, const Rect& scene) {
    if (!frame.moment || !frame.moment->point_known) return;
    const ContactMoment& moment = *frame.moment;
    const std::array<double, 3> at = camera.project(moment.point[0], moment.point[1], moment.point[2]);
    if (at[2] < -1 || at[2] > 1) return;  // behind the camera or past its far plane
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->PushClipRect(ImVec2(float(scene.x), float(scene.y)), ImVec2(float(scene.x + scene.w), float(scene.y + scene.h)));
    const float radius = std::max(12.0f, float(scene.h) / 20.0f);
    const float thickness = std::max(2.5f, float(scene.h) / 240.0f);
    const ImU32 colour = colour32(pass_through_colour());
    const ImVec2 centre{static_cast<float>(at[0]), static_cast<float>(at[1])};
    // The pair's outlines, drawn over the meshes: the pair is often hidden behind a surface.
    for (int side = 0; side < 2; ++side) {
        ImVec2 outline[3];
        bool visible = true;
        for (int k = 0; k < 3; ++k) {
            const std::array<double, 3>& p = moment.corners[3 * side + k];
            const std::array<double, 3> q = camera.project(p[0], p[1], p[2]);
            visible = visible && q[2] >= -1 && q[2] <= 1;
            outline[k] = ImVec2{static_cast<float>(q[0]), static_cast<float>(q[1])};
        }
        if (visible) draw->AddPolyline(outline, 3, colour, ImDrawFlags_Closed, thickness * 0.6f);
    }
    draw->AddCircle(centre, radius, colour, 48, thickness);
    draw->AddCircleFilled(centre, thickness, colour);
    char label[48];
    std::snprintf(label, sizeof label, "first contact t = %.4f", std::max(0.0, moment.toi - 1e-4));
    const ImVec2 size = ImGui::CalcTextSize(label);
    const ImVec2 text{centre.x + radius * 0.75f, centre.y - radius - size.y};
    draw->AddRectFilled(ImVec2(text.x - 2, text.y - 1), ImVec2(text.x + size.x + 2, text.y + size.y + 1), IM_COL32(0, 0, 0, 200), 3.0f);
    draw->AddText(text, colour, label);
    draw->PopClipRect();
}

void draw_pass_through_marks(const std::vector<std::uint64_t>& rows, float x, float y, float height, float step) {
    if (rows.empty()) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 colour = colour32(pass_through_colour());
    const float half = std::clamp(step * 0.5f, 2.0f, 5.0f);
    const float tall = std::max(4.0f, height * 0.18f);
    for (const std::uint64_t row : rows) {
        const float at = x + step * float(row);  // the boundary between row - 1's bar and row's
        draw->AddTriangleFilled(ImVec2(at - half, y), ImVec2(at + half, y), ImVec2(at, y + tall), colour);
    }
}

}  // namespace collidescope::replays
