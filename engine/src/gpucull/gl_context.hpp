#pragma once
// The GL context behind the GPU cull (engine/src/gpucull, private): one small interface, made
// current on the calling thread. OSMesa (Mesa llvmpipe, software, OpenGL 4.5 core) is the
// implementation that always works here.

#include <memory>
#include <string>

namespace collidescope::gpucull {

/// An OpenGL 4.5 core context, current on the thread that made it. Not thread-safe: the thread
/// that created it uses it.
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
