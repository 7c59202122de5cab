#pragma once
/// Which implementation makes the OpenGL context of the GPU cull and the replayer
/// (gl_context.hpp): `--gl auto|osmesa|egl`.

#include <string_view>

namespace collidescope {

enum class GlBackend {
    Auto,    ///< EGL on a hardware device if there is one, else OSMesa, else EGL (software)
    Osmesa,  ///< OSMesa only (Mesa llvmpipe)
    Egl,     ///< EGL only: a hardware device first, then Mesa's software device or platform
};

/// "auto", "osmesa", "egl".
std::string_view gl_backend_name(GlBackend backend);
/// The backend of a name above; throws std::invalid_argument otherwise.
GlBackend parse_gl_backend(std::string_view name);

}  // namespace collidescope
