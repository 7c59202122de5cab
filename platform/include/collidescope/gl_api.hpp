#pragma once
/// The OpenGL entry points collidescope calls, loaded from the GL context that runs them.
///
/// Two implementations of the GL context live in one process (OSMesa and EGL, see
/// gl_context.hpp), and both libraries export the same `gl*` symbols; a call linked to
/// libOSMesa's `glDrawArrays` does nothing under an EGL context (and an NVIDIA EGL driver has
/// its own). So no code here calls a linked GL symbol: each context loads the functions below
/// through its own GetProcAddress into a GlApi, and making it current on a thread selects that
/// table for the thread. In namespace collidescope the functions named like GL's (glClear,
/// glDrawArrays, ...) forward to the current thread's table, so GL code reads as plain GL.
/// tests/platform/check_gl_symbols.sh checks that no library object references a GL symbol directly.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1  // the prototypes give the functions' types (decltype) only
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <cassert>

/// Every GL function collidescope calls (engine, replays and its ImGui renderer).
#define COLLIDESCOPE_GL_FUNCTIONS(X)                                                             \
    X(glActiveTexture) X(glAttachShader) X(glBeginQuery) X(glBindBuffer) X(glBindBufferBase)     \
    X(glBindFramebuffer) X(glBindRenderbuffer) X(glBindTexture) X(glBindVertexArray)             \
    X(glBlendEquation) X(glBlendFuncSeparate) X(glBufferData) X(glCheckFramebufferStatus)        \
    X(glClear) X(glClearBufferSubData) X(glClearColor) X(glClearDepth) X(glCompileShader)        \
    X(glCreateProgram) X(glCreateShader) X(glDeleteBuffers) X(glDeleteFramebuffers)              \
    X(glDeleteProgram) X(glDeleteQueries) X(glDeleteRenderbuffers) X(glDeleteShader)             \
    X(glDeleteTextures) X(glDeleteVertexArrays) X(glDepthFunc) X(glDepthMask) X(glDisable)       \
    X(glDrawArrays) X(glDrawBuffer) X(glDrawElements) X(glDrawElementsBaseVertex) X(glEnable)    \
    X(glEnableVertexAttribArray) X(glEndQuery) X(glFramebufferParameteri)                        \
    X(glFramebufferRenderbuffer) X(glFramebufferTexture2D) X(glGenBuffers) X(glGenFramebuffers)  \
    X(glGenQueries) X(glGenRenderbuffers) X(glGenTextures) X(glGenVertexArrays)                  \
    X(glGetBufferSubData) X(glGetError) X(glGetIntegerv) X(glGetProgramInfoLog) X(glGetProgramiv) \
    X(glGetQueryObjectuiv) X(glGetShaderInfoLog) X(glGetShaderiv) X(glGetString) X(glGetTexImage) \
    X(glGetUniformLocation) X(glLinkProgram) X(glMemoryBarrier) X(glPixelStorei) X(glPolygonMode) \
    X(glProgramUniform2f) X(glReadBuffer) X(glReadPixels) X(glRenderbufferStorage) X(glScissor)  \
    X(glShaderSource) X(glTexBuffer) X(glTexImage2D) X(glTexParameteri) X(glUniform1i)           \
    X(glUniform1ui) X(glUniform3f) X(glUniform3fv) X(glUniformMatrix4fv) X(glUseProgram)         \
    X(glVertexAttribIPointer) X(glVertexAttribPointer) X(glViewport)

namespace collidescope {

/// One context's GL entry points.
struct GlApi {
#define COLLIDESCOPE_GL_MEMBER(name) decltype(&::name) name = nullptr;
    COLLIDESCOPE_GL_FUNCTIONS(COLLIDESCOPE_GL_MEMBER)
#undef COLLIDESCOPE_GL_MEMBER
};

/// GetProcAddress of a GL implementation (OSMesaGetProcAddress, eglGetProcAddress).
using GlProcLoader = void (*(*)(const char* name))();

/// Loads every function of COLLIDESCOPE_GL_FUNCTIONS through `loader`. Throws
/// UnavailableError naming the first function the implementation does not have.
GlApi load_gl_api(GlProcLoader loader, const char* implementation);

/// The table of the context current on this thread (GlContext::make_current sets it). Inline:
/// every GL call reads it.
inline const GlApi*& current_gl_api() {
    thread_local const GlApi* current = nullptr;
    return current;
}

/// Calls below go to the context current on this thread; calling GL with none is a bug.
inline const GlApi& gl_api() {
    assert(current_gl_api() != nullptr && "GL call with no collidescope GL context current");
    return *current_gl_api();
}

/// A call through one member of the current GlApi, with the GL function's own parameter
/// types (so arguments convert at the call site, as with a plain GL prototype).
template <auto Member>
struct GlCall;
template <class R, class... P, R (*GlApi::*Member)(P...)>
struct GlCall<Member> {
    R operator()(P... args) const { return (gl_api().*Member)(args...); }
};

#define COLLIDESCOPE_GL_FORWARD(name) inline constexpr GlCall<&GlApi::name> name{};
COLLIDESCOPE_GL_FUNCTIONS(COLLIDESCOPE_GL_FORWARD)
#undef COLLIDESCOPE_GL_FORWARD

}  // namespace collidescope
