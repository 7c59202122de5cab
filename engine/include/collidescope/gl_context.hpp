#pragma once
/// The OpenGL context behind the GPU cull (Mode 2), offered to the replayer so it renders
/// through the same interface: one small class, made current on the calling thread. OSMesa
/// (Mesa llvmpipe, software, OpenGL 4.5 core) is the implementation that always works here.
/// GL entry points come from libOSMesa itself (GL_GLEXT_PROTOTYPES), not from a loader.

#include <memory>
#include <string>

namespace collidescope::gpucull {

/// An OpenGL 4.5 core context, current on the thread that made it. Not thread-safe: the thread
/// that created it uses it; several contexts may live in several threads at once.
class GlContext {
public:
    virtual ~GlContext() = default;
    /// Makes the context current on the calling thread.
    virtual void make_current() = 0;
    /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    virtual std::string renderer() const = 0;
};

/// Makes an OSMesa context (OpenGL 4.5 core) and makes it current. Throws UnavailableError
/// with the reason when none can be made.
std::unique_ptr<GlContext> make_osmesa_context();

}  // namespace collidescope::gpucull
