#pragma once
/// The OpenGL context (platform/) behind the GPU cull (Mode 2) and the replayer, which render
/// through the same interface: one small class, made current on the calling thread. Two
/// implementations, chosen at run time:
///   - OSMesa (Mesa llvmpipe, software, OpenGL 4.5 core): always works on Debian 12;
///   - EGL without a window (a device of EGL_EXT_platform_device, else Mesa's surfaceless
///     platform): a GPU's driver where there is one, Mesa's llvmpipe otherwise; the future
///     path, since Mesa 25.1 dropped OSMesa.
/// GL entry points are loaded from the context (gl_api.hpp), never linked.

#include "collidescope/gl_api.hpp"
#include "collidescope/gl_backend.hpp"

#include <memory>
#include <string>

namespace collidescope::gl {

/// An OpenGL 4.5 core context with its entry points, current on the thread that made it.
/// Not thread-safe: the thread that created it uses it; several contexts may live in several
/// threads at once. Rendering goes to framebuffer objects (there is no default framebuffer to
/// speak of).
class GlContext {
public:
    virtual ~GlContext() = default;
    /// Makes the context and its GlApi current on the calling thread.
    virtual void make_current() = 0;
    /// GL_RENDERER and the backend, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) via OSMesa".
    virtual std::string renderer() const = 0;
    /// The implementation: GlBackend::Osmesa or GlBackend::Egl.
    virtual GlBackend backend() const = 0;
};

/// Makes a context of `backend` and makes it current. Throws UnavailableError with the
/// reason (every reason tried, for Auto) when none can be made.
std::unique_ptr<GlContext> make_gl_context(GlBackend backend = GlBackend::Auto);

/// The implementations, for make_gl_context and tests. Each throws UnavailableError.
std::unique_ptr<GlContext> make_osmesa_context();
std::unique_ptr<GlContext> make_egl_context();
/// True when EGL offers a device that is not Mesa's software one (a GPU driver).
bool egl_hardware_device_present();

/// Makes `context` current before its GL objects are deleted (in a destructor: a failure,
/// which would leave the objects to the context's own destruction, is not thrown).
void make_current_for_cleanup(GlContext& context) noexcept;

}  // namespace collidescope::gl
