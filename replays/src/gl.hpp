#pragma once
// OpenGL for the replayer (replays/src, private): like the engine's GPU cull, the entry points
// of the context current on this thread (collidescope/gl_api.hpp), never linked ones.

#include "collidescope/gl_api.hpp"
