// Choosing the GL context's implementation at run time (--gl auto|osmesa|egl).

#include "collidescope/gl_context.hpp"

#include "collidescope/error.hpp"

#include <optional>
#include <stdexcept>
#include <string>

namespace collidescope {

std::string_view gl_backend_name(GlBackend backend) { return option_name(k_gl_backend_names, backend); }

GlBackend parse_gl_backend(std::string_view name) {
    if (const std::optional<GlBackend> backend = option_value(k_gl_backend_names, name)) return *backend;
    throw std::invalid_argument("unknown GL backend '" + std::string(name) + "': expected " +
                                option_name_list(k_gl_backend_names));
}

namespace gl {

std::unique_ptr<GlContext> make_gl_context(GlBackend backend) {
    if (backend == GlBackend::Osmesa) return make_osmesa_context();
    if (backend == GlBackend::Egl) return make_egl_context();
    // Auto: a GPU through EGL when there is one; otherwise OSMesa, which always worked here
    // and is the reference; EGL's software renderer when OSMesa is gone (Mesa >= 25.1).
    std::string reasons;
    if (egl_hardware_device_present()) {
        try {
            return make_egl_context();
        } catch (const UnavailableError& error) {
            reasons = std::string(error.what()) + "; ";
        }
    }
    try {
        return make_osmesa_context();
    } catch (const UnavailableError& error) {
        reasons += std::string(error.what()) + "; ";
    }
    try {
        return make_egl_context();
    } catch (const UnavailableError& error) {
        reasons += error.what();
    }
    throw UnavailableError(reasons);
}

void make_current_for_cleanup(GlContext& context) noexcept {
    try {
        context.make_current();
    } catch (const UnavailableError&) {
        // Nothing to do: deleting in another context would be wrong; the context frees its
        // objects when it is destroyed, right after.
        current_gl_api() = nullptr;
    }
}

}  // namespace gl
}  // namespace collidescope
