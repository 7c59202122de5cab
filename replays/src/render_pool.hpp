#pragma once
// Parallel offscreen rendering (replays/src, private): several threads, each with its own GL
// context (the engine's GL context interface: OSMesa or EGL), framebuffer and ImGui overlay, taking frames in order
// from a shared counter.

#include "mesh_renderer.hpp"
#include "overlay.hpp"

#include "collidescope/gl_context.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace collidescope::replays {

/// What one render thread owns, in its own GL context.
struct RenderThread {
    std::unique_ptr<gl::GlContext> context;
    std::unique_ptr<MeshRenderer> renderer;
    std::unique_ptr<Overlay> overlay;
};

/// Makes a GL context of `gl` current on this thread with a width x height framebuffer and an overlay
/// (its font `font_size` pixels; 0: from the height). Throws UnavailableError naming the reason.
RenderThread make_render_thread(GlBackend gl, int width, int height, float font_size = 0);

/// Runs job(thread, i) for i in [0, count) on `threads` threads (0 = hardware threads; never
/// more than count). The first exception stops the others and is rethrown here. Returns the
/// GL_RENDERER of the contexts.
std::string run_parallel(GlBackend gl, int threads, std::uint64_t count, int width, int height,
                         const std::function<void(RenderThread&, std::uint64_t)>& job);

/// The number of threads run_parallel uses for `threads` and `count`.
int render_threads(int threads, std::uint64_t count);

}  // namespace collidescope::replays
