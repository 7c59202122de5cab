#pragma once
// The GL state of the image-space cull (engine/src/gpucull, private): a 32-bit float depth
// buffer of the view's size, the uploaded TriangleQuads, the two programs, a pool of occlusion
// queries and the flag buffer. It draws what it is told; image_space_cull decides what.

#include "collidescope/gl_api.hpp"
#include "gpucull/shaders.hpp"
#include "gpucull/view_quads.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope::gpucull {

/// Draw calls of the cull. Needs a current GL 4.5 context on the calling thread.
class CullRenderer {
public:
    CullRenderer();
    ~CullRenderer();
    CullRenderer(const CullRenderer&) = delete;
    CullRenderer& operator=(const CullRenderer&) = delete;

    /// Uploads the quads of one view and sizes the depth buffer to it; clears the depth.
    void begin_view(std::span<const TriangleQuad> quads, int width, int height);
    /// Clears the depth buffer (to 1: behind every quad, whose depths lie in [0.25, 0.75]).
    void clear_depth();
    /// Draws quads [first, first + count) into the depth buffer (their lower bounds, minimum kept).
    void draw_occluders(std::uint32_t first, std::uint32_t count);
    /// Tests quads [first, first + count) against the depth buffer, one occlusion query per
    /// `per_query` consecutive quads; results come from read_queries, in issue order.
    void test_with_queries(std::uint32_t first, std::uint32_t count, std::uint32_t per_query);
    /// Samples passed of every query issued since the last call (blocks on the GPU).
    std::vector<std::uint32_t> read_queries();
    /// Tests quads [first, first + count) in one draw; the flag of quad id i is set when any of
    /// its fragments is at or behind the depth buffer. Flags persist until clear_flags.
    void test_with_flags(std::uint32_t first, std::uint32_t count);
    /// Zeroes the flags of ids [0, count).
    void clear_flags(std::uint32_t count);
    /// Reads the flags of ids [0, count) (blocks on the GPU).
    std::vector<std::uint32_t> read_flags(std::uint32_t count);
    /// The depth buffer as floats, row-major from the bottom row (for traces and tests).
    std::vector<float> read_depth();
    /// Occlusion queries issued since construction.
    std::uint64_t queries_issued() const { return m_queries_issued; }

private:
    void bind_tester(bool write_flags);
    void resize(int width, int height);

    Program m_occluder;
    Program m_tester;
    GLuint m_vao = 0;
    GLuint m_quads = 0;        ///< vertex buffer of TriangleQuads
    GLuint m_flags = 0;        ///< shader storage buffer, one uint per quad id
    std::size_t m_flag_capacity = 0;
    GLuint m_depth_texture = 0;
    GLuint m_depth_fbo = 0;    ///< depth attachment only: occluders draw here
    GLuint m_test_fbo = 0;     ///< no attachments: testers sample the depth texture
    int m_width = 0;
    int m_height = 0;
    std::vector<GLuint> m_query_pool;
    std::size_t m_queries_pending = 0;
    std::uint64_t m_queries_issued = 0;
};

}  // namespace collidescope::gpucull
