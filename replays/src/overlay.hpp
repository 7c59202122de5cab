#pragma once
// The annotations of a frame, drawn with Dear ImGui into the offscreen framebuffer
// (replays/src, private): the panel, the depth thumbnails and their legend bar, the timeline,
// the colour legend. One Overlay per render thread, in that thread's GL context.
//
// Dear ImGui keeps its current context in a global, so every use of it, in every thread, runs
// under one lock (imgui_lock); the GL drawing it issues is queued by the context and rasterised
// later, outside the lock, when the frame is read back.

#include "frame_data.hpp"

#include "collidescope/replays/camera.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

struct ImGuiContext;

namespace collidescope::replays {

class ImGuiRenderer;

/// What the whole session is, for every frame's annotations.
struct SessionView {
    std::string file;          ///< the recording
    std::string scene;         ///< "demo (default)"
    std::string method;        ///< the method requested when recording
    std::string depth;         ///< the `depth` attribute: off or every:N
    std::uint64_t frames = 0;  ///< frames recorded
    std::vector<std::string> object_names;
    const std::vector<double>* totals = nullptr;         ///< ms.total per row
    const std::vector<int>* modes = nullptr;             ///< frame_mode per row
    const std::vector<std::uint32_t>* indices = nullptr;  ///< scene frame per row
    const std::vector<RegionLife>* lives = nullptr;        ///< regions' rows (record --regions)
    /// Rows whose interval into them has pass-throughs (record --between-frames).
    const std::vector<std::uint64_t>* pass_through_rows = nullptr;
};

/// "Mode 1 (AABB)", "Mode 2 (GPU cull)", "hybrid", "brute".
const char* mode_name(int mode);
/// The timeline's colour of a mode (RGB in [0, 1]).
std::array<float, 3> mode_colour(int mode);
/// The depth thumbnails' colour map (viridis) at window depth `t` in [0, 1].
std::array<std::uint8_t, 3> depth_colour(double t);

/// The one lock around every use of Dear ImGui.
std::mutex& imgui_lock();

class Overlay {
public:
    /// An ImGui context drawn by an ImGuiRenderer in the current GL context, for width x height
    /// images; the font is DejaVu Sans when installed (fonts-dejavu-core), else ImGui's own, of
    /// `font_size` pixels (0: from the height).
    Overlay(int width, int height, float font_size = 0);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    /// Draws the frame's annotation layers over the bound framebuffer.
    /// `camera` (the frame's) places the regions' curves; nullptr: no curves.
    void draw_frame(const FrameData& frame, const SessionView& session, const FrameLayout& layout, unsigned layers,
                    const Camera* camera = nullptr);
    /// Runs `build` (ImGui calls) twice and draws the second result: layouts that ImGui settles
    /// over one frame come out the same whatever this context drew before (determinism).
    void draw(const std::function<void()>& build);
    float font_size() const { return m_font_size; }

private:
    ImGuiContext* m_context = nullptr;
    std::unique_ptr<ImGuiRenderer> m_renderer;
    int m_width;
    int m_height;
    float m_font_size;
};

/// An RGBA texture in the current GL context, deleted with the object.
class Texture {
public:
    Texture(const std::vector<std::uint8_t>& rgba, int width, int height);
    ~Texture();
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;
    unsigned id() const { return m_id; }

private:
    unsigned m_id = 0;
};

/// A depth image as RGBA through depth_colour, top row first; window depth 1 (nothing drawn) black.
std::vector<std::uint8_t> depth_rgba(const GpuDepthImage& image);

}  // namespace collidescope::replays
