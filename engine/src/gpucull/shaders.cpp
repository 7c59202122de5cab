// GLSL sources of the cull and their compilation. The depth bounds evaluated here are those of
// view_quads.hpp (quad_depth_bound); `precise` keeps the compiler from reassociating them.

#include "gpucull/shaders.hpp"

#include "collidescope/error.hpp"

#include <initializer_list>
#include <vector>

namespace collidescope::gpucull {
namespace {

constexpr const char* k_vertex = R"(#version 450 core
layout(location = 0) in vec4 rect;
layout(location = 1) in vec4 plane;
layout(location = 2) in vec2 range;
layout(location = 3) in uint id;
layout(location = 4) in float edge_margin;
layout(location = 5) in vec3 e0;
layout(location = 6) in vec3 e1;
layout(location = 7) in vec3 e2;
out Quad { flat vec4 rect; flat vec4 plane; flat vec2 range; flat uint id; flat float margin; flat mat3 edges; } quad;
void main() {
    quad.rect = rect; quad.plane = plane; quad.range = range; quad.id = id;
    quad.margin = edge_margin; quad.edges = mat3(e0, e1, e2);
}
)";

// Pixel rectangle -> clip space; z is irrelevant (the fragment shaders own depth).
constexpr const char* k_geometry = R"(#version 450 core
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 viewport;
in Quad { flat vec4 rect; flat vec4 plane; flat vec2 range; flat uint id; flat float margin; flat mat3 edges; } quad[];
flat out vec4 plane;
flat out vec2 range;
flat out uint id;
flat out float edge_margin;
flat out mat3 edges;
void corner(float x, float y) {
    plane = quad[0].plane; range = quad[0].range; id = quad[0].id;
    edge_margin = quad[0].margin; edges = quad[0].edges;
    gl_Position = vec4(2.0 * x / viewport.x - 1.0, 2.0 * y / viewport.y - 1.0, 0.5, 1.0);
    EmitVertex();
}
void main() {
    vec4 r = quad[0].rect;
    corner(r.x, r.y); corner(r.z, r.y); corner(r.x, r.w); corner(r.z, r.w);
    EndPrimitive();
}
)";

// Shared by both fragment shaders: the pixel's square lies on the inner side of every edge
// line, up to the margin (view_quads.hpp, quad_covers).
constexpr const char* k_coverage = R"(#version 450 core
flat in vec4 plane;
flat in vec2 range;
flat in uint id;
flat in float edge_margin;
flat in mat3 edges;
bool covers() {
    for (int i = 0; i < 3; ++i) {
        precise float distance = edges[i].x * gl_FragCoord.x + edges[i].y * gl_FragCoord.y + edges[i].z;
        if (distance > 0.5 * (abs(edges[i].x) + abs(edges[i].y)) + edge_margin) return false;
    }
    return true;
}
)";

constexpr const char* k_occluder = R"(
void main() {
    if (!covers()) discard;
    precise float z = plane.x * gl_FragCoord.x + plane.y * gl_FragCoord.y + plane.z;
    precise float spread = 0.5 * (abs(plane.x) + abs(plane.y)) + plane.w;
    gl_FragDepth = max(z - spread, range.x);
}
)";

constexpr const char* k_tester = R"(
layout(binding = 0) uniform sampler2D occluder_depth;
layout(std430, binding = 1) buffer Flags { uint flags[]; };
uniform int write_flags;
void main() {
    if (!covers()) discard;
    precise float z = plane.x * gl_FragCoord.x + plane.y * gl_FragCoord.y + plane.z;
    precise float spread = 0.5 * (abs(plane.x) + abs(plane.y)) + plane.w;
    float upper = min(z + spread, range.y);
    float occluder = texelFetch(occluder_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (upper < occluder) discard;  // strictly in front of everything drawn in this pixel
    if (write_flags != 0) flags[id] = 1u;
}
)";

// Compiles the concatenation of `sources`.
GLuint compile(GLenum stage, std::initializer_list<const char*> sources) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, static_cast<GLsizei>(sources.size()), sources.begin(), nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == 0) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1);
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw UnavailableError(std::string("GPU cull unavailable: shader does not compile: ") + log.data());
    }
    return shader;
}

}  // namespace

Program::Program(const char* vertex, const char* geometry, const char* fragment) {
    // Every fragment shader starts with the shared coverage test.
    const GLuint stages[] = {compile(GL_VERTEX_SHADER, {vertex}), compile(GL_GEOMETRY_SHADER, {geometry}),
                             compile(GL_FRAGMENT_SHADER, {k_coverage, fragment})};
    m_id = glCreateProgram();
    for (const GLuint stage : stages) glAttachShader(m_id, stage);
    glLinkProgram(m_id);
    for (const GLuint stage : stages) glDeleteShader(stage);
    GLint ok = 0;
    glGetProgramiv(m_id, GL_LINK_STATUS, &ok);
    if (ok == 0) {
        char log[2048] = {};
        glGetProgramInfoLog(m_id, sizeof log, nullptr, log);
        throw UnavailableError(std::string("GPU cull unavailable: program does not link: ") + log);
    }
}

Program::~Program() {
    if (m_id != 0 && current_gl_api() != nullptr) glDeleteProgram(m_id);  // else freed with the context
}

Program& Program::operator=(Program&& other) noexcept {
    if (this != &other) {
        if (m_id != 0) glDeleteProgram(m_id);
        m_id = other.m_id;
        other.m_id = 0;
    }
    return *this;
}

Program make_occluder_program() { return Program(k_vertex, k_geometry, k_occluder); }

Program make_tester_program() { return Program(k_vertex, k_geometry, k_tester); }

}  // namespace collidescope::gpucull
