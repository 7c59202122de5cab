#pragma once
// Draws Dear ImGui's output (ImDrawData) with the replayer's own GL calls (replays/src,
// private): ImGui's renderer contract, not its OpenGL3 backend. The backend Debian ships inside
// libimgui.a loads GL itself and finds no context under OSMesa, and its source is only under
// /usr/share/doc, which container images strip; this renderer needs neither, and calls GL through
// the current context's table (collidescope/gl_api.hpp) like the rest of the replayer.
//
// The contract (imgui.h, "ImDrawData"): upload the font atlas as a texture and give ImGui its
// id; per draw list, upload its vertices and indices; per command, scissor to ClipRect, bind
// the command's texture and draw ElemCount indices from IdxOffset, VtxOffset added to each.

#include "collidescope/gl_api.hpp"

struct ImDrawData;

namespace collidescope::replays {

class ImGuiRenderer {
public:
    /// Program, buffers and the font atlas texture of the current ImGui context (its fonts
    /// already added), in the current GL 4.5 context; sets the atlas's texture id and tells
    /// ImGui that VtxOffset is honoured. Throws UnavailableError when the shaders fail.
    ImGuiRenderer();
    ~ImGuiRenderer();
    ImGuiRenderer(const ImGuiRenderer&) = delete;
    ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

    /// Draws `data` over the bound framebuffer, alpha blended, as ImGui lays it out (pixels,
    /// origin top left). Leaves blending, the scissor test and the depth test off and no
    /// program, vertex array or texture bound.
    void render(const ImDrawData& data);

private:
    GLuint m_program = 0;
    GLint m_projection = -1;
    GLuint m_vertex_array = 0;
    GLuint m_vertex_buffer = 0;
    GLuint m_index_buffer = 0;
    GLuint m_font_texture = 0;
};

}  // namespace collidescope::replays
