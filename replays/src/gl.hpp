#pragma once
// OpenGL declarations for the replayer (replays/src, private). Like the engine's GPU cull, GL
// entry points come from libOSMesa itself (GL_GLEXT_PROTOTYPES), not from a loader.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
