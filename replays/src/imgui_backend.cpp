// Dear ImGui's OpenGL3 backend, as Debian ships it (libimgui-dev 1.86), compiled here with
// IMGUI_IMPL_OPENGL_LOADER_CUSTOM: libimgui.a's copy carries its own loader (imgl3w), which
// dlopens libGL and finds no context under OSMesa ("Failed to initialize OpenGL loader!").
// Compiled this way it calls the GL entry points libOSMesa exports, as the engine does; the
// linker then takes these definitions and never pulls libimgui.a's backend object.

#include "gl.hpp"

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
