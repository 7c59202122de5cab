#pragma once
// The GLSL programs of the image-space cull (engine/src/gpucull, private). Both draw each
// triangle as its TriangleQuad: a point expanded by a geometry shader into the quad's pixel
// rectangle (conservative coverage: llvmpipe has no conservative rasterization).
//  - occluder: writes, per pixel, the lower depth bound of the triangle (depth test LESS, so
//    the buffer keeps the minimum over everything drawn).
//  - tester: reads that buffer as a texture and keeps (does not discard) a fragment when the
//    triangle's upper depth bound over the pixel is at or behind it; with `write_flags` it also
//    sets the triangle's flag in a shader storage buffer (the query-free variant).

#include "collidescope/gl_api.hpp"

#include <string>

namespace collidescope::gpucull {

/// A linked program; deletes it on destruction.
class Program {
public:
    Program() = default;
    /// Compiles and links the stages (the fragment stage after the shared coverage test).
    /// Throws UnavailableError with the driver's log on failure.
    Program(const char* vertex, const char* geometry, const char* fragment);
    ~Program();
    Program(Program&& other) noexcept : m_id(other.m_id) { other.m_id = 0; }
    Program& operator=(Program&& other) noexcept;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;
    GLuint id() const { return m_id; }

private:
    GLuint m_id = 0;
};

/// The occluder program (uniform `viewport`: vec2 width, height).
Program make_occluder_program();

/// The tester program (uniforms `viewport`, `write_flags`; texture unit 0: the occluder depth;
/// shader storage binding 1: the flags).
Program make_tester_program();

}  // namespace collidescope::gpucull
