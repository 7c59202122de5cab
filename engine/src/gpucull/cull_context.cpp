// The GPU cull's GL context: the platform's, with the cull's name on its failure.

#include "gpucull/cull_context.hpp"

#include "collidescope/error.hpp"

#include <string>

namespace collidescope::gpucull {

std::unique_ptr<GlContext> make_cull_context(GlBackend backend) {
    try {
        return gl::make_gl_context(backend);
    } catch (const UnavailableError& error) {
        throw UnavailableError(std::string("GPU cull unavailable: ") + error.what());
    }
}

}  // namespace collidescope::gpucull
