#pragma once
// OpenGL declarations for the GPU cull (engine/src/gpucull, private). GL entry points come from
// libOSMesa itself (GL_GLEXT_PROTOTYPES): libepoxy does not resolve them under OSMesa.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
