// The Dear ImGui context of a render thread, the lock around ImGui, textures, colour maps.

#include "overlay.hpp"

#include "collidescope/gl_api.hpp"
#include "imgui_renderer.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace collidescope::replays {
namespace {

constexpr const char* k_font_file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

const char* mode_name(int mode) {
    switch (mode) {
    case 1: return "Mode 1 (AABB)";
    case 2: return "Mode 2 (GPU cull)";
    case 3: return "hybrid (AABB + GPU)";
    default: return "brute force";
    }
}

std::array<float, 3> mode_colour(int mode) {
    switch (mode) {
    case 1: return {0.30f, 0.60f, 1.00f};
    case 2: return {1.00f, 0.60f, 0.15f};
    case 3: return {0.75f, 0.45f, 1.00f};
    default: return {0.60f, 0.60f, 0.60f};
    }
}

std::array<std::uint8_t, 3> depth_colour(double t) {
    // viridis at 0, 1/4, 1/2, 3/4, 1, linearly interpolated
    static constexpr std::array<std::array<double, 3>, 5> k_stops = {{
        {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const auto i = std::min<std::size_t>(std::size_t(t), 3);
    const double f = t - double(i);
    std::array<std::uint8_t, 3> c{};
    for (std::size_t k = 0; k < 3; ++k) c[k] = std::uint8_t(std::lround(k_stops[i][k] * (1 - f) + k_stops[i + 1][k] * f));
    return c;
}

std::vector<std::uint8_t> depth_rgba(const GpuDepthImage& image) {
    std::vector<std::uint8_t> rgba(std::size_t(image.width) * image.height * 4);
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            // GL rows are bottom first; the texture rows go top first.
            const float depth = image.depth[std::size_t(image.height - 1 - y) * image.width + x];
            std::uint8_t* p = &rgba[(std::size_t(y) * image.width + x) * 4];
            const std::array<std::uint8_t, 3> c =
                depth >= 1.0f ? std::array<std::uint8_t, 3>{0, 0, 0} : depth_colour(double(depth));
            p[0] = c[0];
            p[1] = c[1];
            p[2] = c[2];
            p[3] = 255;
        }
    }
    return rgba;
}

std::mutex& imgui_lock() {
    static std::mutex lock;
    return lock;
}

Overlay::Overlay(int width, int height, float font_size)
    : m_width(width), m_height(height),
      m_font_size(font_size > 0 ? font_size : std::clamp(float(height) / 48.0f, 11.0f, 22.0f)) {
    const std::lock_guard<std::mutex> guard(imgui_lock());
    m_context = ImGui::CreateContext();
    ImGui::SetCurrentContext(m_context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 30.0f;
    if (std::filesystem::exists(k_font_file)) {
        io.Fonts->AddFontFromFileTTF(k_font_file, m_font_size);
    } else {
        ImFontConfig config;
        config.SizePixels = std::round(m_font_size);
        io.Fonts->AddFontDefault(&config);
    }
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0;
    style.WindowBorderSize = 0;
    style.WindowPadding = ImVec2(m_font_size * 0.6f, m_font_size * 0.5f);
    style.ItemSpacing = ImVec2(m_font_size * 0.5f, m_font_size * 0.25f);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.05f, 0.06f, 0.08f, 0.92f);
    m_renderer = std::make_unique<ImGuiRenderer>();
}

Overlay::~Overlay() {
    const std::lock_guard<std::mutex> guard(imgui_lock());
    ImGui::SetCurrentContext(m_context);
    m_renderer.reset();
    ImGui::DestroyContext(m_context);
}

void Overlay::draw(const std::function<void()>& build) {
    const std::lock_guard<std::mutex> guard(imgui_lock());
    ImGui::SetCurrentContext(m_context);
    for (int pass = 0; pass < 2; ++pass) {
        ImGui::NewFrame();
        build();
        ImGui::Render();
    }
    m_renderer->render(*ImGui::GetDrawData());
}

Texture::Texture(const std::vector<std::uint8_t>& rgba, int width, int height) {
    glGenTextures(1, &m_id);
    glBindTexture(GL_TEXTURE_2D, m_id);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

Texture::~Texture() { glDeleteTextures(1, &m_id); }

}  // namespace collidescope::replays
