// SharedLibrary (collidescope/shared_library.hpp): dlopen and dlsym.

#include "collidescope/shared_library.hpp"

#include "collidescope/error.hpp"

#include <dlfcn.h>

#include <utility>

namespace collidescope {
namespace {

std::string loader_reason() {
    const char* reason = dlerror();
    return reason != nullptr ? reason : "unknown reason";
}

}  // namespace

SharedLibrary::SharedLibrary(std::string soname) : m_soname(std::move(soname)) {
    m_handle = dlopen(m_soname.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (m_handle == nullptr) throw UnavailableError(m_soname + ": " + loader_reason());
}

void* SharedLibrary::address(const char* name) const {
    dlerror();  // clears an earlier error
    void* address = dlsym(m_handle, name);
    if (address == nullptr) throw UnavailableError(m_soname + ": no function " + name + " (" + loader_reason() + ")");
    return address;
}

}  // namespace collidescope
