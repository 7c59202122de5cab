// Loading the GL entry points from a context's GetProcAddress.

#include "collidescope/gl_api.hpp"

#include "collidescope/error.hpp"

#include <string>

namespace collidescope {

GlApi load_gl_api(GlProcLoader loader, const char* implementation) {
    GlApi api;
    // void (*)() converts to any function pointer type without -Wcast-function-type.
#define COLLIDESCOPE_GL_LOAD(name)                                                               \
    api.name = reinterpret_cast<decltype(api.name)>(loader(#name));                               \
    if (api.name == nullptr) {                                                                   \
        throw UnavailableError(std::string(implementation) + " has no entry point " + #name);  \
    }
    COLLIDESCOPE_GL_FUNCTIONS(COLLIDESCOPE_GL_LOAD)
#undef COLLIDESCOPE_GL_LOAD
    return api;
}

}  // namespace collidescope
