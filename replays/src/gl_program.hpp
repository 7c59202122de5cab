#pragma once
// Shader programs of the replayer (replays/src, private): compiled and linked in the current
// GL context, errors as UnavailableError naming what failed.

#include "collidescope/gl_api.hpp"

namespace collidescope::replays {

/// The program of one vertex and one fragment shader (GLSL source). `what` names it in the
/// error ("mesh", "overlay"). Throws UnavailableError with the compiler's log.
GLuint link_program(const char* vertex_source, const char* fragment_source, const char* what);

}  // namespace collidescope::replays
