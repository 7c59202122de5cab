// Dear ImGui's OpenGL3 backend, as Debian ships it (libimgui-dev 1.86), compiled here with
// IMGUI_IMPL_OPENGL_LOADER_CUSTOM: libimgui.a's copy carries its own loader (imgl3w), which
// dlopens libGL and finds no context under OSMesa ("Failed to initialize OpenGL loader!").
// Compiled this way, and with every GL name it calls defined below as the current context's
// entry point (collidescope/gl_api.hpp; the backend's code sits in the global namespace, where
// the forwarding functions of namespace collidescope are not seen), it runs on OSMesa and EGL
// alike. The linker takes these definitions and never pulls libimgui.a's backend object.
// tests/gpucull/check_gl_symbols.sh fails if one GL name below is missing.

#include "gl.hpp"

#define COLLIDESCOPE_IMGUI_GL(name) (::collidescope::gl_api().name)
#define glActiveTexture COLLIDESCOPE_IMGUI_GL(glActiveTexture)
#define glAttachShader COLLIDESCOPE_IMGUI_GL(glAttachShader)
#define glBindBuffer COLLIDESCOPE_IMGUI_GL(glBindBuffer)
#define glBindSampler COLLIDESCOPE_IMGUI_GL(glBindSampler)
#define glBindTexture COLLIDESCOPE_IMGUI_GL(glBindTexture)
#define glBindVertexArray COLLIDESCOPE_IMGUI_GL(glBindVertexArray)
#define glBlendEquation COLLIDESCOPE_IMGUI_GL(glBlendEquation)
#define glBlendEquationSeparate COLLIDESCOPE_IMGUI_GL(glBlendEquationSeparate)
#define glBlendFuncSeparate COLLIDESCOPE_IMGUI_GL(glBlendFuncSeparate)
#define glBufferData COLLIDESCOPE_IMGUI_GL(glBufferData)
#define glBufferSubData COLLIDESCOPE_IMGUI_GL(glBufferSubData)
#define glClipControl COLLIDESCOPE_IMGUI_GL(glClipControl)
#define glCompileShader COLLIDESCOPE_IMGUI_GL(glCompileShader)
#define glCreateProgram COLLIDESCOPE_IMGUI_GL(glCreateProgram)
#define glCreateShader COLLIDESCOPE_IMGUI_GL(glCreateShader)
#define glDeleteBuffers COLLIDESCOPE_IMGUI_GL(glDeleteBuffers)
#define glDeleteProgram COLLIDESCOPE_IMGUI_GL(glDeleteProgram)
#define glDeleteShader COLLIDESCOPE_IMGUI_GL(glDeleteShader)
#define glDeleteTextures COLLIDESCOPE_IMGUI_GL(glDeleteTextures)
#define glDeleteVertexArrays COLLIDESCOPE_IMGUI_GL(glDeleteVertexArrays)
#define glDetachShader COLLIDESCOPE_IMGUI_GL(glDetachShader)
#define glDisable COLLIDESCOPE_IMGUI_GL(glDisable)
#define glDrawElements COLLIDESCOPE_IMGUI_GL(glDrawElements)
#define glDrawElementsBaseVertex COLLIDESCOPE_IMGUI_GL(glDrawElementsBaseVertex)
#define glEnable COLLIDESCOPE_IMGUI_GL(glEnable)
#define glEnableVertexAttribArray COLLIDESCOPE_IMGUI_GL(glEnableVertexAttribArray)
#define glGenBuffers COLLIDESCOPE_IMGUI_GL(glGenBuffers)
#define glGenTextures COLLIDESCOPE_IMGUI_GL(glGenTextures)
#define glGenVertexArrays COLLIDESCOPE_IMGUI_GL(glGenVertexArrays)
#define glGetAttribLocation COLLIDESCOPE_IMGUI_GL(glGetAttribLocation)
#define glGetError COLLIDESCOPE_IMGUI_GL(glGetError)
#define glGetIntegerv COLLIDESCOPE_IMGUI_GL(glGetIntegerv)
#define glGetProgramInfoLog COLLIDESCOPE_IMGUI_GL(glGetProgramInfoLog)
#define glGetProgramiv COLLIDESCOPE_IMGUI_GL(glGetProgramiv)
#define glGetShaderInfoLog COLLIDESCOPE_IMGUI_GL(glGetShaderInfoLog)
#define glGetShaderiv COLLIDESCOPE_IMGUI_GL(glGetShaderiv)
#define glGetString COLLIDESCOPE_IMGUI_GL(glGetString)
#define glGetStringi COLLIDESCOPE_IMGUI_GL(glGetStringi)
#define glGetUniformLocation COLLIDESCOPE_IMGUI_GL(glGetUniformLocation)
#define glIsEnabled COLLIDESCOPE_IMGUI_GL(glIsEnabled)
#define glLinkProgram COLLIDESCOPE_IMGUI_GL(glLinkProgram)
#define glPixelStorei COLLIDESCOPE_IMGUI_GL(glPixelStorei)
#define glPolygonMode COLLIDESCOPE_IMGUI_GL(glPolygonMode)
#define glScissor COLLIDESCOPE_IMGUI_GL(glScissor)
#define glShaderSource COLLIDESCOPE_IMGUI_GL(glShaderSource)
#define glTexImage2D COLLIDESCOPE_IMGUI_GL(glTexImage2D)
#define glTexParameteri COLLIDESCOPE_IMGUI_GL(glTexParameteri)
#define glUniform1i COLLIDESCOPE_IMGUI_GL(glUniform1i)
#define glUniformMatrix4fv COLLIDESCOPE_IMGUI_GL(glUniformMatrix4fv)
#define glUseProgram COLLIDESCOPE_IMGUI_GL(glUseProgram)
#define glVertexAttribPointer COLLIDESCOPE_IMGUI_GL(glVertexAttribPointer)
#define glViewport COLLIDESCOPE_IMGUI_GL(glViewport)

#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#include IMGUI_OPENGL3_BACKEND_SOURCE
#pragma GCC diagnostic pop
