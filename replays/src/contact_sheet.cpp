// The contact sheet: selection, layout, rendering.

#include "contact_sheet.hpp"

#include "mesh_renderer.hpp"
#include "png.hpp"
#include "render_pool.hpp"

#include <imgui.h>

#include <algorithm>
#include <memory>
#include <numeric>

namespace collidescope::replays {
namespace {

constexpr int k_columns = 4;

std::vector<std::uint64_t> evenly_spaced(const std::vector<std::uint64_t>& candidates, int count) {
    if (candidates.size() <= std::size_t(count)) return candidates;
    std::vector<std::uint64_t> picked;
    for (int i = 0; i < count; ++i) {
        // first and last included, the rest evenly between
        const std::size_t at = count == 1 ? 0 : std::size_t(i) * (candidates.size() - 1) / std::size_t(count - 1);
        picked.push_back(candidates[at]);
    }
    picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
    return picked;
}

const char* short_mode_name(int mode) {
    switch (mode) {
    case 1: return "Mode 1";
    case 2: return "Mode 2";
    case 3: return "hybrid";
    default: return "brute";
    }
}

const char* selection_name(SheetSelection selection) {
    switch (selection) {
    case SheetSelection::Every: return "evenly spaced frames";
    case SheetSelection::Collisions: return "frames with collisions";
    case SheetSelection::Slowest: return "slowest frames";
    }
    return "";
}

}  // namespace

TileSize sheet_tile_size(int width, int height) {
    const int tile_width = std::min(width, 400);
    return {tile_width, std::max(1, height * tile_width / std::max(width, 1))};
}

std::vector<std::uint64_t> select_sheet_frames(SheetSelection selection, int count, const std::vector<double>& totals,
                                               const std::vector<std::uint64_t>& pairs) {
    std::vector<std::uint64_t> all(totals.size());
    std::iota(all.begin(), all.end(), 0);
    if (count <= 0) return {};
    switch (selection) {
    case SheetSelection::Every: return evenly_spaced(all, count);
    case SheetSelection::Collisions: {
        std::vector<std::uint64_t> colliding;
        for (const std::uint64_t i : all) {
            if (pairs[i] > 0) colliding.push_back(i);
        }
        return evenly_spaced(colliding, count);
    }
    case SheetSelection::Slowest: {
        std::stable_sort(all.begin(), all.end(), [&](std::uint64_t a, std::uint64_t b) { return totals[a] > totals[b]; });
        all.resize(std::min(all.size(), std::size_t(count)));
        std::sort(all.begin(), all.end());
        return all;
    }
    }
    return {};
}

void write_contact_sheet(const std::filesystem::path& file, const std::vector<SheetTile>& tiles, const TileSize& tile,
                         const SessionView& session, SheetSelection selection, GlBackend gl) {
    const int columns = std::max(1, std::min(k_columns, int(tiles.size())));
    const int rows = std::max(1, int((tiles.size() + std::size_t(columns) - 1) / std::size_t(columns)));
    const float font = std::clamp(float(tile.width) / 28.0f, 11.0f, 15.0f);
    const int gap = int(font * 0.6f);
    const int caption = int(font * 1.5f);
    const int header = int(font * 3.6f);
    const int width = columns * tile.width + (columns + 1) * gap;
    const int height = header + rows * (tile.height + caption + gap) + gap;
    RenderThread thread = make_render_thread(gl, width, height, font);
    std::vector<std::unique_ptr<Texture>> textures;
    for (const SheetTile& one : tiles) textures.push_back(std::make_unique<Texture>(one.rgba, tile.width, tile.height));
    thread.renderer->clear();
    thread.overlay->draw([&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(float(width), float(height)));
        ImGui::Begin("sheet", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground);
        ImGui::SetCursorPos(ImVec2(float(gap), float(gap)));
        ImGui::Text("%s  -  scene %s, method %s  -  %s", session.file.c_str(), session.scene.c_str(),
                    session.method.c_str(), selection_name(selection));
        ImDrawList* draw = ImGui::GetWindowDrawList();
        float x = float(gap);
        const float y = float(gap) + ImGui::GetFontSize() * 1.5f;
        auto swatch = [&](const std::array<float, 3>& c, const char* label) {
            const float s = ImGui::GetFontSize();
            draw->AddRectFilled(ImVec2(x, y + 1), ImVec2(x + s, y + s),
                                ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1)));
            ImGui::SetCursorPos(ImVec2(x + s * 1.3f, y));
            ImGui::Text("%s", label);
            x += s * 1.3f + ImGui::CalcTextSize(label).x + s;
        };
        for (std::size_t k = 0; k < session.object_names.size() && k < 4; ++k) {
            swatch(object_colour(std::uint32_t(k)), session.object_names[k].c_str());
        }
        swatch(state_colour(k_state_colliding), "colliding");
        swatch(state_colour(k_state_pcs), "in PCS after GPU cull");
        swatch(state_colour(k_state_culled), "culled");
        for (int mode = 1; mode <= 3; ++mode) swatch(mode_colour(mode), mode_name(mode));
        for (std::size_t i = 0; i < tiles.size(); ++i) {
            const int column = int(i) % columns;
            const int row = int(i) / columns;
            const float tx = float(gap + column * (tile.width + gap));
            const float ty = float(header + row * (tile.height + caption + gap));
            ImGui::SetCursorPos(ImVec2(tx, ty));
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(textures[i]->id())),
                         ImVec2(float(tile.width), float(tile.height)));
            const std::array<float, 3> c = mode_colour(tiles[i].mode);
            draw->AddRectFilled(ImVec2(tx, ty + float(tile.height)), ImVec2(tx + font * 0.6f, ty + float(tile.height + caption)),
                                ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1)));
            ImGui::SetCursorPos(ImVec2(tx + font, ty + float(tile.height) + font * 0.2f));
            ImGui::Text("frame %u   %s   %llu pairs   %.1f ms", tiles[i].frame, short_mode_name(tiles[i].mode),
                        static_cast<unsigned long long>(tiles[i].pairs), tiles[i].total_ms);
        }
        ImGui::End();
    });
    write_png(file, thread.renderer->read_rgba(), width, height);
}

}  // namespace collidescope::replays
