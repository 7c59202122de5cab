// GL objects and draw calls of the cull.

#include "gpucull/cull_renderer.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <cstddef>
#include <string>

namespace collidescope::gpucull {
namespace {

void attribute(GLuint index, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(TriangleQuad),
                          reinterpret_cast<const void*>(offset));
}

}  // namespace

CullRenderer::CullRenderer() : m_occluder(make_occluder_program()), m_tester(make_tester_program()) {
    glGenVertexArrays(1, &m_vao);
    glBindVertexArray(m_vao);
    glGenBuffers(1, &m_quads);
    glBindBuffer(GL_ARRAY_BUFFER, m_quads);
    attribute(0, 4, offsetof(TriangleQuad, x0));
    attribute(1, 4, offsetof(TriangleQuad, a));
    attribute(2, 2, offsetof(TriangleQuad, zlo));
    glEnableVertexAttribArray(3);
    glVertexAttribIPointer(3, 1, GL_UNSIGNED_INT, sizeof(TriangleQuad),
                           reinterpret_cast<const void*>(offsetof(TriangleQuad, id)));
    attribute(4, 1, offsetof(TriangleQuad, edge_margin));
    for (GLuint edge = 0; edge < 3; ++edge) attribute(5 + edge, 3, offsetof(TriangleQuad, edges) + edge * 3 * sizeof(float));
    glGenBuffers(1, &m_flags);
    glGenTextures(1, &m_depth_texture);
    glGenFramebuffers(1, &m_depth_fbo);
    glGenFramebuffers(1, &m_test_fbo);
    // Depth never clips: the quads' depths are in [0.25, 0.75] and gl_FragDepth sets them.
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_CULL_FACE);
    if (glGetError() != GL_NO_ERROR) throw UnavailableError("GPU cull unavailable: GL setup failed");
}

CullRenderer::~CullRenderer() {
    if (current_gl_api() == nullptr) return;  // no context current: its destruction frees these
    if (!m_query_pool.empty()) glDeleteQueries(static_cast<GLsizei>(m_query_pool.size()), m_query_pool.data());
    glDeleteFramebuffers(1, &m_test_fbo);
    glDeleteFramebuffers(1, &m_depth_fbo);
    glDeleteTextures(1, &m_depth_texture);
    glDeleteBuffers(1, &m_flags);
    glDeleteBuffers(1, &m_quads);
    glDeleteVertexArrays(1, &m_vao);
}

void CullRenderer::resize(int width, int height) {
    if (width == m_width && height == m_height) return;
    m_width = width;
    m_height = height;
    glBindTexture(GL_TEXTURE_2D, m_depth_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindFramebuffer(GL_FRAMEBUFFER, m_depth_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth_texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    const GLenum depth_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, m_test_fbo);
    glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    const GLenum test_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (depth_status != GL_FRAMEBUFFER_COMPLETE || test_status != GL_FRAMEBUFFER_COMPLETE) {
        throw UnavailableError("GPU cull unavailable: framebuffer of " + std::to_string(width) + "x" +
                               std::to_string(height) + " is incomplete");
    }
    glViewport(0, 0, width, height);
}

void CullRenderer::begin_view(std::span<const TriangleQuad> quads, int width, int height) {
    resize(width, height);
    glBindBuffer(GL_ARRAY_BUFFER, m_quads);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quads.size_bytes()), quads.data(), GL_STREAM_DRAW);
    for (const GLuint program : {m_occluder.id(), m_tester.id()}) {
        glProgramUniform2f(program, glGetUniformLocation(program, "viewport"), static_cast<float>(width),
                           static_cast<float>(height));
    }
    clear_depth();
}

void CullRenderer::clear_depth() {
    glBindFramebuffer(GL_FRAMEBUFFER, m_depth_fbo);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
}

void CullRenderer::draw_occluders(std::uint32_t first, std::uint32_t count) {
    if (count == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, m_depth_fbo);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glUseProgram(m_occluder.id());
    glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(count));
}

void CullRenderer::bind_tester(bool write_flags) {
    glBindFramebuffer(GL_FRAMEBUFFER, m_test_fbo);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(m_tester.id());
    glUniform1i(glGetUniformLocation(m_tester.id(), "write_flags"), write_flags ? 1 : 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_depth_texture);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m_flags);
}

void CullRenderer::test_with_queries(std::uint32_t first, std::uint32_t count, std::uint32_t per_query) {
    if (count == 0) return;
    bind_tester(false);
    per_query = std::max<std::uint32_t>(per_query, 1);
    for (std::uint32_t at = 0; at < count; at += per_query) {
        if (m_queries_pending == m_query_pool.size()) {
            const std::size_t grow = std::max<std::size_t>(64, m_query_pool.size());
            m_query_pool.resize(m_query_pool.size() + grow);
            glGenQueries(static_cast<GLsizei>(grow), m_query_pool.data() + m_query_pool.size() - grow);
        }
        glBeginQuery(GL_SAMPLES_PASSED, m_query_pool[m_queries_pending++]);
        glDrawArrays(GL_POINTS, static_cast<GLint>(first + at), static_cast<GLsizei>(std::min(per_query, count - at)));
        glEndQuery(GL_SAMPLES_PASSED);
        ++m_queries_issued;
    }
}

std::vector<std::uint32_t> CullRenderer::read_queries() {
    std::vector<std::uint32_t> samples(m_queries_pending);
    for (std::size_t i = 0; i < m_queries_pending; ++i) {
        GLuint value = 0;
        glGetQueryObjectuiv(m_query_pool[i], GL_QUERY_RESULT, &value);
        samples[i] = value;
    }
    m_queries_pending = 0;
    return samples;
}

void CullRenderer::clear_flags(std::uint32_t count) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_flags);
    if (count > m_flag_capacity) {
        m_flag_capacity = std::max<std::size_t>(count, 2 * m_flag_capacity);
        glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(m_flag_capacity * sizeof(GLuint)), nullptr,
                     GL_DYNAMIC_COPY);
    }
    const GLuint zero = 0;
    glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, 0, static_cast<GLsizeiptr>(count * sizeof(GLuint)),
                         GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void CullRenderer::test_with_flags(std::uint32_t first, std::uint32_t count) {
    if (count == 0) return;
    bind_tester(true);
    glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(count));
}

std::vector<std::uint32_t> CullRenderer::read_flags(std::uint32_t count) {
    std::vector<std::uint32_t> flags(count);
    if (count == 0) return flags;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_flags);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(GLuint)), flags.data());
    return flags;
}

std::vector<float> CullRenderer::read_depth() {
    std::vector<float> depth(static_cast<std::size_t>(m_width) * static_cast<std::size_t>(m_height));
    glBindTexture(GL_TEXTURE_2D, m_depth_texture);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

}  // namespace collidescope::gpucull
