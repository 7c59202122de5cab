#pragma once
/// A shared library opened at run time (dlopen). The GL contexts and the video encoders load
/// theirs on first use, so a command that renders and encodes nothing (check, validate,
/// inspect) never loads Mesa's OSMesa, with LLVM, nor FFmpeg with its codecs: together 165 of
/// the 200 ms that each start of `collidescope` took on the project's VM (about 170 libraries
/// of 200), and 275 ms under AddressSanitizer, where the test suite starts it thousands of
/// times (docs/explanation/architecture.md, "Libraries loaded on first use").

#include <string>

namespace collidescope {

class SharedLibrary {
public:
    /// Opens `soname` (dlopen, RTLD_NOW | RTLD_LOCAL). Throws UnavailableError
    /// "<soname>: <the loader's reason>". The library stays loaded for the rest of the process:
    /// nothing is unloaded (Mesa and FFmpeg keep thread-local state and exit handlers).
    explicit SharedLibrary(std::string soname);

    /// The address of the function `name`. Throws UnavailableError "<soname>: no function
    /// <name> (<reason>)".
    void* address(const char* name) const;

    /// address(name) as a pointer of type `Function` (decltype(&::name) keeps it in step with
    /// the library's header).
    template <class Function>
    Function function(const char* name) const {
        return reinterpret_cast<Function>(address(name));
    }

    const std::string& soname() const { return m_soname; }

private:
    std::string m_soname;
    void* m_handle = nullptr;
};

}  // namespace collidescope
