#pragma once
// The GL context behind the GPU cull: declared in the public header, since the replayer renders
// through the same interface (collidescope/gl_context.hpp).

#include "collidescope/gl_context.hpp"
