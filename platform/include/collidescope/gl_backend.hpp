#pragma once
/// Which implementation makes the OpenGL context of the GPU cull and the replayer
/// (gl_context.hpp): `--gl auto|osmesa|egl`.

#include "collidescope/option_names.hpp"

#include <string_view>

namespace collidescope {

enum class GlBackend {
    Auto,    ///< EGL on a hardware device if there is one, else OSMesa, else EGL (software)
    Osmesa,  ///< OSMesa only (Mesa llvmpipe)
    Egl,     ///< EGL only: a hardware device first, then Mesa's software device or platform
};

/// The names of GlBackend (--gl).
inline constexpr OptionNames<GlBackend, 3> k_gl_backend_names{
    {{"auto", GlBackend::Auto}, {"osmesa", GlBackend::Osmesa}, {"egl", GlBackend::Egl}}};

/// The backend's name in k_gl_backend_names.
std::string_view gl_backend_name(GlBackend backend);
/// The backend of a name in k_gl_backend_names; throws std::invalid_argument otherwise.
GlBackend parse_gl_backend(std::string_view name);

}  // namespace collidescope
