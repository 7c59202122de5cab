// ImGui's draw lists through the replayer's GL entry points (imgui_renderer.hpp).

#include "imgui_renderer.hpp"

#include "gl_program.hpp"

#include <imgui.h>

#include <cstddef>
#include <cstdint>

namespace collidescope::replays {
namespace {

// Positions in ImGui's pixels (origin top left, y down) to clip space; colours are sRGB bytes
// normalised by the vertex fetch, multiplied with the texture (the font atlas is white where
// a glyph is, so untextured shapes sample its white pixel).
constexpr const char* k_imgui_vertex_shader = R"(#version 450 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;
uniform mat4 projection;
out vec2 frag_uv;
out vec4 frag_colour;
void main() {
    frag_uv = uv;
    frag_colour = colour;
    gl_Position = projection * vec4(position, 0.0, 1.0);
}
)";

constexpr const char* k_imgui_fragment_shader = R"(#version 450 core
in vec2 frag_uv;
in vec4 frag_colour;
uniform sampler2D atlas;
out vec4 out_colour;
void main() {
    out_colour = frag_colour * texture(atlas, frag_uv);
}
)";

// GL's texture name from ImGui's ImTextureID (the replayer stores names as integers).
GLuint texture_name(ImTextureID id) {
    return static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(id));
}

void vertex_attribute(GLuint index, GLint size, GLenum type, GLboolean normalised, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, type, normalised, sizeof(ImDrawVert),
                          reinterpret_cast<const void*>(offset));
}

// Orthographic projection of ImGui's display rectangle (column-major, y flipped).
void set_projection(GLint location, const ImDrawData& data) {
    const float l = data.DisplayPos.x;
    const float r = data.DisplayPos.x + data.DisplaySize.x;
    const float t = data.DisplayPos.y;
    const float b = data.DisplayPos.y + data.DisplaySize.y;
    const float projection[16] = {
        2.0f / (r - l),    0.0f,              0.0f,  0.0f,
        0.0f,              2.0f / (t - b),    0.0f,  0.0f,
        0.0f,              0.0f,              -1.0f, 0.0f,
        (r + l) / (l - r), (t + b) / (b - t), 0.0f,  1.0f,
    };
    glUniformMatrix4fv(location, 1, GL_FALSE, projection);
}

}  // namespace

ImGuiRenderer::ImGuiRenderer() {
    m_program = link_program(k_imgui_vertex_shader, k_imgui_fragment_shader, "overlay");
    m_projection = glGetUniformLocation(m_program, "projection");
    glUseProgram(m_program);
    glUniform1i(glGetUniformLocation(m_program, "atlas"), 0);
    glUseProgram(0);

    glGenVertexArrays(1, &m_vertex_array);
    glGenBuffers(1, &m_vertex_buffer);
    glGenBuffers(1, &m_index_buffer);
    glBindVertexArray(m_vertex_array);
    glBindBuffer(GL_ARRAY_BUFFER, m_vertex_buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_index_buffer);  // recorded in the vertex array
    vertex_attribute(0, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, pos));
    vertex_attribute(1, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, uv));
    vertex_attribute(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(ImDrawVert, col));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = "collidescope_replays";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    unsigned char* pixels = nullptr;
    int width = 0;
    int height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    glGenTextures(1, &m_font_texture);
    glBindTexture(GL_TEXTURE_2D, m_font_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glBindTexture(GL_TEXTURE_2D, 0);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(m_font_texture)));
}

ImGuiRenderer::~ImGuiRenderer() {
    ImGui::GetIO().Fonts->SetTexID(nullptr);
    glDeleteTextures(1, &m_font_texture);
    glDeleteBuffers(1, &m_index_buffer);
    glDeleteBuffers(1, &m_vertex_buffer);
    glDeleteVertexArrays(1, &m_vertex_array);
    glDeleteProgram(m_program);
}

void ImGuiRenderer::render(const ImDrawData& data) {
    const float scale_x = data.FramebufferScale.x;
    const float scale_y = data.FramebufferScale.y;
    const int framebuffer_width = static_cast<int>(data.DisplaySize.x * scale_x);
    const int framebuffer_height = static_cast<int>(data.DisplaySize.y * scale_y);
    if (framebuffer_width <= 0 || framebuffer_height <= 0) return;

    glViewport(0, 0, framebuffer_width, framebuffer_height);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUseProgram(m_program);
    set_projection(m_projection, data);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(m_vertex_array);
    glBindBuffer(GL_ARRAY_BUFFER, m_vertex_buffer);

    constexpr GLenum index_type = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
    for (int l = 0; l < data.CmdListsCount; ++l) {
        const ImDrawList& list = *data.CmdLists[l];
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.VtxBuffer.size_in_bytes()), list.VtxBuffer.Data,
                     GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.IdxBuffer.size_in_bytes()),
                     list.IdxBuffer.Data, GL_STREAM_DRAW);
        for (int c = 0; c < list.CmdBuffer.Size; ++c) {
            const ImDrawCmd& command = list.CmdBuffer[c];
            // The replayer adds no callbacks; ImGui's reset request needs nothing here, since
            // every command sets the state it depends on.
            if (command.UserCallback != nullptr) continue;
            // ClipRect is in ImGui's pixels (origin top left); GL's scissor box has its origin
            // bottom left, in framebuffer pixels.
            const float x0 = (command.ClipRect.x - data.DisplayPos.x) * scale_x;
            const float y0 = (command.ClipRect.y - data.DisplayPos.y) * scale_y;
            const float x1 = (command.ClipRect.z - data.DisplayPos.x) * scale_x;
            const float y1 = (command.ClipRect.w - data.DisplayPos.y) * scale_y;
            if (x1 <= x0 || y1 <= y0) continue;
            glScissor(static_cast<GLint>(x0), static_cast<GLint>(static_cast<float>(framebuffer_height) - y1),
                      static_cast<GLsizei>(x1 - x0), static_cast<GLsizei>(y1 - y0));
            glBindTexture(GL_TEXTURE_2D, texture_name(command.GetTexID()));
            glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(command.ElemCount), index_type,
                                     reinterpret_cast<const void*>(command.IdxOffset * sizeof(ImDrawIdx)),
                                     static_cast<GLint>(command.VtxOffset));
        }
    }

    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
}

}  // namespace collidescope::replays
