// Shader compilation and linking, shared by the mesh renderer and the ImGui renderer.

#include "gl_program.hpp"

#include "collidescope/error.hpp"

#include <string>

namespace collidescope::replays {
namespace {

GLuint compile(GLenum type, const char* source, const char* what) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == 0) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        glDeleteShader(shader);
        throw UnavailableError(std::string("replay: ") + what + " shader does not compile: " + log);
    }
    return shader;
}

}  // namespace

GLuint link_program(const char* vertex_source, const char* fragment_source, const char* what) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, what);
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source, what);
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok == 0) {
        glDeleteProgram(program);
        throw UnavailableError(std::string("replay: ") + what + " shader program does not link");
    }
    return program;
}

}  // namespace collidescope::replays
