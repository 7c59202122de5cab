// What the overlay shows on a replayed frame: the panel (frame, mode, decision, stage times,
// pairs, PCS per pass, queries, view matrix), the depth thumbnails, the timeline, the legend.

#include "mesh_renderer.hpp"
#include "overlay.hpp"
#include "overlay_colour.hpp"
#include "overlay_moment.hpp"
#include "overlay_regions.hpp"
#include "overlay_text.hpp"

#include "collidescope/stats.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace collidescope::replays {
namespace {

constexpr ImGuiWindowFlags k_window = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                      ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus;
constexpr const char* k_axes = "xyz";

std::string format(const char* pattern, double value) { return measured(pattern, value, "-"); }

bool begin_window(const char* name, const Rect& rect) {
    ImGui::SetNextWindowPos(ImVec2(float(rect.x), float(rect.y)));
    ImGui::SetNextWindowSize(ImVec2(float(rect.w), float(rect.h)));
    return ImGui::Begin(name, nullptr, k_window);
}

void heading(const char* text) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.55f, 0.80f, 1.0f, 1.0f), "%s", text);
}

void decision_lines(const FrameData& frame) {
    heading("Decision (thesis 4.4)");
    const std::vector<std::string> lines = decision_text(frame);
    if (frame.decision.empty()) {
        ImGui::PushTextWrapPos(0);
        ImGui::TextDisabled("%s", lines.front().c_str());
        ImGui::PopTextWrapPos();
        return;
    }
    for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
}

void stage_bars(const FrameData& frame) {
    const double total = value_of(frame.stage_ms, "total");
    heading(format("Time per stage (total %.3f ms)", total).c_str());
    const float width = ImGui::GetContentRegionAvail().x;
    for (const auto& [name, ms] : frame.stage_ms) {
        if (name == "total" || ms <= 0) continue;
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float bar = total > 0 ? float(ms / total) * width * 0.45f : 0.0f;
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x + width * 0.55f, at.y + 2),
                                                  ImVec2(at.x + width * 0.55f + bar, at.y + ImGui::GetFontSize() - 1),
                                                  IM_COL32(90, 160, 255, 200));
        ImGui::Text("%-15s %9.3f", name.c_str(), ms);
    }
}

void pair_lines(const FrameData& frame) {
    heading("Pairs");
    ImGui::Text("colliding %.0f   candidates %.0f", value_of(frame.counts, "colliding_pairs"),
                value_of(frame.counts, "candidate_pairs"));
    ImGui::Text("object pairs %.0f   exact tests %.0f", value_of(frame.counts, "object_pairs"),
                value_of(frame.counts, "exact_tests"));
    ImGui::Text("triangles %.0f", value_of(frame.counts, "triangles"));
    if (const std::optional<std::string> aabb = aabb_text(frame)) ImGui::TextUnformatted(aabb->c_str());
    if (const std::optional<std::string> hybrid = hybrid_text(frame)) ImGui::TextUnformatted(hybrid->c_str());
}

void view_matrix(const FrameData& frame) {
    const float cell = std::min(ImGui::GetFontSize() * 2.6f, ImGui::GetContentRegionAvail().x / 3.0f);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    double largest = 0;
    for (int pass = 0; pass < 3; ++pass) {
        for (int view = 0; view < 3; ++view) {
            largest = std::max(largest, value_of(frame.gpu, std::string("view_matrix_") + char('0' + pass) + k_axes[view]));
        }
    }
    for (int pass = 0; pass < 3; ++pass) {
        for (int view = 0; view < 3; ++view) {
            const double value = value_of(frame.gpu, std::string("view_matrix_") + char('0' + pass) + k_axes[view]);
            const double t = largest > 0 ? value / largest : 0.0;
            const std::array<std::uint8_t, 3> c = depth_colour(t);
            const ImVec2 a(at.x + float(view) * cell, at.y + float(pass) * cell * 0.6f);
            const ImVec2 b(a.x + cell - 2, a.y + cell * 0.6f - 2);
            draw->AddRectFilled(a, b, IM_COL32(c[0], c[1], c[2], 255));
            const std::string text = format("%.2f", value);
            draw->AddText(ImVec2(a.x + 3, a.y + 1), t > 0.6 ? IM_COL32(0, 0, 0, 255) : IM_COL32(255, 255, 255, 255),
                          text.c_str());
        }
    }
    ImGui::Dummy(ImVec2(cell * 3, cell * 1.8f));
}

void gpu_lines(const FrameData& frame) {
    heading("GPU cull (Mode 2)");
    if (frame.gpu.empty()) {
        ImGui::TextDisabled("did not run on this frame (method %s)", frame.method.c_str());
        return;
    }
    ImGui::Text("PCS objects %.0f -> %.0f, triangles %.0f -> %.0f", value_of(frame.gpu, "pcs_objects_in"),
                value_of(frame.gpu, "pcs_objects_out"), value_of(frame.gpu, "pcs_triangles_in"),
                value_of(frame.gpu, "pcs_triangles_out"));
    ImGui::TextUnformatted(gpu_queries_text(frame).c_str());
    ImGui::TextDisabled("pass       tested hidden queries   samples  P");
    for (const GpuPassInfo& pass : frame.passes) {
        ImGui::Text("%s %c %s %7u %6u %7u %9llu %2u", pass.level == 0 ? "obj" : "tri", k_axes[pass.view % 3],
                    pass.reverse != 0 ? "rev" : "fwd", pass.items_tested, pass.items_hidden, pass.queries,
                    static_cast<unsigned long long>(pass.samples_passed), pass.triangles_per_query);
    }
}

// On a moment-of-contact image: which interval, when, which pair, and what else passed through.
void moment_lines(const FrameData& frame, const SessionView& session) {
    const ContactMoment& m = *frame.moment;
    const std::array<float, 3> c = pass_through_colour();
    ImGui::TextColored(ImVec4(c[0], c[1], c[2], 1), "between frames %u and %u, t = %.4f", frame.frame, m.to_frame,
                       std::max(0.0, m.toi - 1e-4));
    const auto name = [&](std::uint32_t object) {
        return object < session.object_names.size() ? session.object_names[object] : std::to_string(object);
    };
    const TrianglePair& p = m.first.front();
    ImGui::Text("first contact: %s #%u / %s #%u", name(p.obj_a).c_str(), p.tri_a, name(p.obj_b).c_str(), p.tri_b);
    if (m.first.size() > 1) ImGui::Text("  and %zu more pairs at that time", m.first.size() - 1);
    ImGui::Text("a pass-through: apart at both frames");
    if (!m.resolved) ImGui::TextDisabled("unresolved: within the tolerance not proven");
    ImGui::Text("interval: %llu pairs, %llu pass-throughs", static_cast<unsigned long long>(m.contacts),
                static_cast<unsigned long long>(m.pass_throughs));
    ImGui::TextDisabled("meshes interpolated; stats: frame %u", frame.frame);
}

void panel(const FrameData& frame, const SessionView& session, const Rect& rect) {
    if (begin_window("panel", rect)) {
        ImGui::TextColored(ImVec4(1, 1, 1, 1), "frame %u   (%llu/%llu recorded)", frame.frame,
                           static_cast<unsigned long long>(frame.row + 1), static_cast<unsigned long long>(session.frames));
        if (frame.moment) moment_lines(frame, session);
        ImGui::Text("scene %s", session.scene.c_str());
        const int mode = frame_mode(frame.method, frame.decision);
        const std::array<float, 3> c = mode_colour(mode);
        ImGui::Text("method %s,", frame.method.c_str());
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(c[0], c[1], c[2], 1), "%s", mode_name(mode));
        decision_lines(frame);
        pair_lines(frame);
        stage_bars(frame);
        gpu_lines(frame);
    }
    ImGui::End();
}

void depth_column(const FrameData& frame, const SessionView& session, const Rect& rect,
                  const std::vector<std::unique_ptr<Texture>>& textures) {
    if (begin_window("depth", rect)) {
        heading("GPU cull depth buffers");
        const float width = ImGui::GetContentRegionAvail().x;
        const float line = ImGui::GetTextLineHeightWithSpacing();
        // The colour bar and the view matrix keep their place at the bottom; the thumbnails
        // share what is above them.
        const float reserve = line * 6.0f + ImGui::GetFontSize() + std::min(ImGui::GetFontSize() * 2.6f, width / 3.0f) * 1.8f;
        const float bottom = float(rect.h) - reserve;
        if (frame.depth_images.empty()) {
            ImGui::PushTextWrapPos(0);
            if (session.depth == "off" || session.depth.empty()) {
                ImGui::TextDisabled("not recorded in this recording (record --depth every:N)");
            } else {
                ImGui::TextDisabled("none on this frame (recorded: %s, GPU cull frames only)", session.depth.c_str());
            }
            ImGui::PopTextWrapPos();
        } else {
            ImGui::TextDisabled("axis: near .. far");
        }
        const float each = frame.depth_images.empty()
                               ? 0.0f
                               : (bottom - ImGui::GetCursorPosY()) / float(frame.depth_images.size()) - line;
        for (std::size_t i = 0; i < frame.depth_images.size(); ++i) {
            const GpuDepthImage& image = frame.depth_images[i];
            const float aspect = image.width > 0 ? float(image.height) / float(image.width) : 1.0f;
            const float w = std::max(1.0f, std::min(width, each / aspect));
            ImGui::Text("%c %s: %s .. %s", k_axes[image.view % 3], image.level == 0 ? "obj" : "tri",
                        format("%.3g", image.depth_near).c_str(), format("%.3g", image.depth_far).c_str());
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(textures[i]->id())),
                         ImVec2(w, w * aspect));
        }
        // The legend bar: fixed range, window depth 0 (near) .. 1 (far), black = nothing drawn.
        ImGui::SetCursorPosY(std::max(ImGui::GetCursorPosY(), bottom));
        ImGui::TextColored(ImVec4(0.55f, 0.80f, 1.0f, 1.0f), "depth (window, fixed range)");
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float bar_h = ImGui::GetFontSize();
        ImDrawList* draw = ImGui::GetWindowDrawList();
        constexpr int k_steps = 48;
        for (int s = 0; s < k_steps; ++s) {
            const std::array<std::uint8_t, 3> c = depth_colour((s + 0.5) / k_steps);
            draw->AddRectFilled(ImVec2(at.x + width * float(s) / k_steps, at.y),
                                ImVec2(at.x + width * float(s + 1) / k_steps, at.y + bar_h), IM_COL32(c[0], c[1], c[2], 255));
        }
        ImGui::Dummy(ImVec2(width, bar_h));
        ImGui::Text("0 near");
        ImGui::SameLine(width * 0.72f);
        ImGui::Text("1 far");
        ImGui::TextDisabled("input length units; black: empty");
        ImGui::TextColored(ImVec4(0.55f, 0.80f, 1.0f, 1.0f), "View matrix (4.2.1)");
        if (frame.gpu.empty()) {
            ImGui::TextDisabled("no GPU cull on this frame");
        } else {
            ImGui::TextDisabled("rows: pass; columns: x y z");
            view_matrix(frame);
        }
    }
    ImGui::End();
}

void timeline(const FrameData& frame, const SessionView& session, const Rect& rect, unsigned layers) {
    if (begin_window("timeline", rect)) {
        const std::vector<double>& totals = *session.totals;
        const double largest = totals.empty() ? 0.0 : *std::max_element(totals.begin(), totals.end());
        ImGui::Text("total ms per frame (max %.2f ms)", largest);
        for (int mode = 1; mode <= 3; ++mode) {
            ImGui::SameLine();
            const std::array<float, 3> c = mode_colour(mode);
            ImGui::TextColored(ImVec4(c[0], c[1], c[2], 1), "  %s", mode_name(mode));
        }
        if (session.pass_through_rows != nullptr && !session.pass_through_rows->empty()) {
            ImGui::SameLine();
            const std::array<float, 3> c = pass_through_colour();
            ImGui::TextColored(ImVec4(c[0], c[1], c[2], 1), "  v pass-through between frames");
        }
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const ImVec2 size = ImGui::GetContentRegionAvail();
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const float step = totals.empty() ? 0.0f : size.x / float(totals.size());
        for (std::size_t row = 0; row < totals.size(); ++row) {
            const float h = largest > 0 ? float(totals[row] / largest) * size.y : 0.0f;
            const float x = at.x + step * float(row);
            draw->AddRectFilled(ImVec2(x, at.y + size.y - std::max(h, 1.0f)), ImVec2(x + std::max(step - 1, 1.0f), at.y + size.y),
                                colour32(mode_colour((*session.modes)[row])));
        }
        if ((layers & k_layer_regions) != 0 && session.lives != nullptr) {
            draw_region_lives(*session.lives, at.x, at.y, size.x, size.y, step);
        }
        if (session.pass_through_rows != nullptr) draw_pass_through_marks(*session.pass_through_rows, at.x, at.y, size.y, step);
        // A moment of contact sits between its two frames' bars, at its time.
        const float x = at.x + step * (float(frame.row) + 0.5f + (frame.moment ? float(frame.moment->toi) : 0.0f));
        draw->AddLine(ImVec2(x, at.y), ImVec2(x, at.y + size.y), IM_COL32(255, 255, 255, 255), 2.0f);
    }
    ImGui::End();
}

void swatch(const std::array<float, 3>& c, const char* label) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float s = ImGui::GetFontSize();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, at.y + 1), ImVec2(at.x + s, at.y + s), colour32(c));
    ImGui::Dummy(ImVec2(s, s));
    ImGui::SameLine();
    ImGui::Text("%s", label);
    ImGui::SameLine();
}

void legend(const FrameData& frame, const SessionView& session, const Rect& rect, unsigned layers) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetFontSize() * 0.5f, 2));
    if (begin_window("legend", rect)) {
        for (std::size_t k = 0; k < session.object_names.size() && k < 4; ++k) {
            swatch(object_colour(std::uint32_t(k)), session.object_names[k].c_str());
        }
        if ((layers & k_layer_collisions) != 0) {
            swatch(state_colour(k_state_colliding), frame.moment ? "first contact (pass-through)" : "colliding");
        }
        if ((layers & k_layer_pcs) != 0) {
            if (frame.pcs_recorded) {
                swatch(state_colour(k_state_pcs), "in PCS after cull");
                swatch(state_colour(k_state_culled), "culled");
            } else {
                ImGui::TextDisabled("PCS: not recorded (%s)", frame.method.c_str());
            }
        }
        if ((layers & k_layer_regions) != 0 && !frame.regions.empty()) swatch(region_colour(1), "curves (R#: region)");
        if (frame.positions_dropped) ImGui::TextDisabled("positions dropped (--budget)");
        ImGui::NewLine();
    }
    ImGui::End();
    ImGui::PopStyleVar();
}

}  // namespace

void Overlay::draw_frame(const FrameData& frame, const SessionView& session, const FrameLayout& layout, unsigned layers,
                         const Camera* camera) {
    std::vector<std::unique_ptr<Texture>> textures;
    if ((layers & k_layer_depth) != 0) {
        for (const GpuDepthImage& image : frame.depth_images) {
            textures.push_back(std::make_unique<Texture>(depth_rgba(image), int(image.width), int(image.height)));
        }
    }
    draw([&] {
        if ((layers & k_layer_regions) != 0 && camera != nullptr) draw_region_curves(frame, *camera, layout.scene);
        if ((layers & k_layer_collisions) != 0 && camera != nullptr) draw_contact_marker(frame, *camera, layout.scene);
        if ((layers & k_layer_overlay) != 0) panel(frame, session, layout.panel);
        if ((layers & k_layer_depth) != 0) depth_column(frame, session, layout.depth, textures);
        if ((layers & k_layer_timeline) != 0) timeline(frame, session, layout.timeline, layers);
        if ((layers & k_layer_legend) != 0) legend(frame, session, layout.legend, layers);
    });
}

}  // namespace collidescope::replays
