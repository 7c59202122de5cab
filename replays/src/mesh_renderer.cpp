// The meshes of a frame, flat shaded, coloured by object and triangle state.

#include "mesh_renderer.hpp"

#include "gl_program.hpp"

#include "collidescope/error.hpp"

#include <string>

namespace collidescope::replays {
namespace {

constexpr const char* k_mesh_vertex_shader = R"(#version 450 core
layout(location = 0) in vec3 position;
uniform mat4 u_view_projection;
out vec3 v_world;
void main() {
    v_world = position;
    gl_Position = u_view_projection * vec4(position, 1.0);
}
)";

// The face normal comes from the screen-space derivatives of the world position (flat shading
// without per-vertex normals); lighting is two-sided, a headlight plus a key light from above.
constexpr const char* k_mesh_fragment_shader = R"(#version 450 core
in vec3 v_world;
uniform usamplerBuffer u_states;
uniform vec3 u_base;
uniform vec3 u_eye;
uniform vec3 u_key;
uniform uint u_layers;
uniform vec3 u_state_colours[5];
out vec4 colour;
void main() {
    vec3 n = cross(dFdx(v_world), dFdy(v_world));
    vec3 view = normalize(u_eye - v_world);
    n = dot(n, n) > 0.0 ? normalize(n) : view;
    float light = 0.25 + 0.5 * abs(dot(n, view)) + 0.25 * abs(dot(n, u_key));
    uint state = texelFetch(u_states, gl_PrimitiveID).r;
    bool collisions = (u_layers & 2u) != 0u;
    bool pcs = (u_layers & 4u) != 0u;
    vec3 albedo = u_base;
    if (state == 4u || (state == 3u && collisions)) {
        albedo = u_state_colours[state];
    } else if (pcs && state >= 2u) {
        albedo = u_state_colours[2];
    } else if (pcs && state == 1u) {
        albedo = mix(vec3(dot(u_base, vec3(0.3333))), u_base, 0.25) * 0.5;
    }
    colour = vec4(albedo * light, 1.0);
}
)";

constexpr std::array<float, 3> k_background = {0.11f, 0.12f, 0.14f};

}  // namespace

std::array<float, 3> object_colour(std::uint32_t object) {
    static constexpr std::array<float, 3> k_palette[] = {
        {0.30f, 0.55f, 0.95f},  // blue
        {0.25f, 0.78f, 0.78f},  // teal
        {0.68f, 0.52f, 0.92f},  // violet
        {0.80f, 0.80f, 0.82f},  // light grey
        {0.45f, 0.62f, 0.80f},  // steel
        {0.85f, 0.55f, 0.80f},  // pink
    };
    return k_palette[object % std::size(k_palette)];
}

std::array<float, 3> state_colour(TriangleState state) {
    switch (state) {
    case k_state_culled: return {0.28f, 0.28f, 0.30f};
    case k_state_pcs: return {1.00f, 0.72f, 0.10f};
    case k_state_colliding: return {0.95f, 0.06f, 0.06f};
    case k_state_only_here: return {0.10f, 1.00f, 0.25f};
    case k_state_plain: break;
    }
    return {0.6f, 0.6f, 0.6f};
}

MeshRenderer::MeshRenderer(int width, int height) : m_width(width), m_height(height) {
    glGenFramebuffers(1, &m_framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    glGenRenderbuffers(1, &m_colour);
    glBindRenderbuffer(GL_RENDERBUFFER, m_colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour);
    glGenRenderbuffers(1, &m_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw UnavailableError("replay: cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                               " framebuffer");
    }
    m_program = link_program(k_mesh_vertex_shader, k_mesh_fragment_shader, "mesh");
}

MeshRenderer::~MeshRenderer() {
    for (auto& [key, entry] : m_meshes) {
        Mesh& mesh = entry.second;
        glDeleteVertexArrays(1, &mesh.vao);
        glDeleteBuffers(1, &mesh.vertices);
        glDeleteBuffers(1, &mesh.indices);
        glDeleteBuffers(1, &mesh.states);
        glDeleteTextures(1, &mesh.states_texture);
    }
    glDeleteProgram(m_program);
    glDeleteRenderbuffers(1, &m_colour);
    glDeleteRenderbuffers(1, &m_depth);
    glDeleteFramebuffers(1, &m_framebuffer);
}

void MeshRenderer::clear() {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    glViewport(0, 0, m_width, m_height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(k_background[0], k_background[1], k_background[2], 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

MeshRenderer::Mesh& MeshRenderer::mesh_for(std::uint32_t source, std::uint32_t object, const ObjectFrame& frame) {
    auto [it, inserted] = m_meshes.try_emplace({source, object});
    auto& [topology, mesh] = it->second;
    if (inserted) {
        glGenVertexArrays(1, &mesh.vao);
        glGenBuffers(1, &mesh.vertices);
        glGenBuffers(1, &mesh.indices);
        glGenBuffers(1, &mesh.states);
        glGenTextures(1, &mesh.states_texture);
        glBindVertexArray(mesh.vao);
        glBindBuffer(GL_ARRAY_BUFFER, mesh.vertices);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glEnableVertexAttribArray(0);
    }
    glBindVertexArray(mesh.vao);
    if (inserted || topology != frame.topology) {
        topology = frame.topology;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(frame.triangles->size() * sizeof(TriIndices)),
                     frame.triangles->data(), GL_STATIC_DRAW);
        mesh.index_count = GLsizei(frame.triangles->size() * 3);
    }
    return mesh;
}

void MeshRenderer::draw(const FrameData& frame, const Camera& camera, unsigned layers, std::uint32_t source) {
    if ((layers & k_layer_meshes) == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    // GL's viewport origin is the bottom left; the layout's is the top left.
    glViewport(camera.viewport.x, m_height - camera.viewport.y - camera.viewport.h, camera.viewport.w,
               camera.viewport.h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(m_program);
    const std::array<float, 16> view_projection = camera.view_projection();
    glUniformMatrix4fv(glGetUniformLocation(m_program, "u_view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform3f(glGetUniformLocation(m_program, "u_eye"), float(camera.eye[0]), float(camera.eye[1]),
                float(camera.eye[2]));
    glUniform3f(glGetUniformLocation(m_program, "u_key"), 0.36f, 0.48f, 0.80f);
    glUniform1ui(glGetUniformLocation(m_program, "u_layers"), layers);
    glUniform1i(glGetUniformLocation(m_program, "u_states"), 0);
    std::array<float, 15> states{};
    for (std::uint8_t s = 0; s < 5; ++s) {
        const std::array<float, 3> c = state_colour(TriangleState(s));
        for (int i = 0; i < 3; ++i) states[std::size_t(s * 3 + i)] = c[std::size_t(i)];
    }
    glUniform3fv(glGetUniformLocation(m_program, "u_state_colours"), 5, states.data());
    glActiveTexture(GL_TEXTURE0);
    for (std::uint32_t object = 0; object < frame.objects.size(); ++object) {
        const ObjectFrame& one = frame.objects[object];
        if (one.positions.empty() || one.triangles->empty()) continue;
        Mesh& mesh = mesh_for(source, object, one);
        glBindBuffer(GL_ARRAY_BUFFER, mesh.vertices);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(one.positions.size() * sizeof(float)), one.positions.data(),
                     GL_STREAM_DRAW);
        glBindBuffer(GL_TEXTURE_BUFFER, mesh.states);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(one.states.size()), one.states.data(), GL_STREAM_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, mesh.states_texture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R8UI, mesh.states);
        const std::array<float, 3> base = object_colour(object);
        glUniform3f(glGetUniformLocation(m_program, "u_base"), base[0], base[1], base[2]);
        glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, m_width, m_height);
}

std::vector<std::uint8_t> MeshRenderer::read_rgba() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    const std::size_t stride = std::size_t(m_width) * 4;
    std::vector<std::uint8_t> bottom_up(stride * std::size_t(m_height));
    glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    std::vector<std::uint8_t> rgba(bottom_up.size());
    for (int y = 0; y < m_height; ++y) {
        std::copy_n(bottom_up.data() + std::size_t(m_height - 1 - y) * stride, stride, rgba.data() + std::size_t(y) * stride);
    }
    return rgba;
}

}  // namespace collidescope::replays
