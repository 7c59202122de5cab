#pragma once
// OpenGL for the GPU cull (engine/src/gpucull, private): GL's types and constants, and the
// entry points of the context current on this thread (collidescope/gl_api.hpp).

#include "collidescope/gl_api.hpp"
