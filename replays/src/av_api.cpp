// av() (av_api.hpp): FFmpeg's libraries opened by soname, each function looked up in its own.

#include "av_api.hpp"

#include "collidescope/error.hpp"
#include "collidescope/shared_library.hpp"

#include <string>
#include <variant>

namespace collidescope::replays {
namespace {

std::string soname(const char* library, int major) { return "lib" + std::string(library) + ".so." + std::to_string(major); }

using Loaded = std::variant<AvFunctions, std::string>;

Loaded load() {
    try {
        // libavutil first: the others need it, and a missing one is named by its own soname.
        const SharedLibrary avutil(soname("avutil", LIBAVUTIL_VERSION_MAJOR));
        const SharedLibrary swscale(soname("swscale", LIBSWSCALE_VERSION_MAJOR));
        const SharedLibrary avcodec(soname("avcodec", LIBAVCODEC_VERSION_MAJOR));
        const SharedLibrary avformat(soname("avformat", LIBAVFORMAT_VERSION_MAJOR));
        const SharedLibrary avfilter(soname("avfilter", LIBAVFILTER_VERSION_MAJOR));
        AvFunctions functions;
#define COLLIDESCOPE_AV_LOAD(library, name) functions.name = library.function<decltype(&::name)>(#name);
        COLLIDESCOPE_AV_FUNCTIONS(COLLIDESCOPE_AV_LOAD)
#undef COLLIDESCOPE_AV_LOAD
        return functions;
    } catch (const UnavailableError& error) {
        return std::string("FFmpeg: ") + error.what();
    }
}

}  // namespace

const AvFunctions& av() {
    static const Loaded loaded = load();
    if (const auto* reason = std::get_if<std::string>(&loaded)) throw UnavailableError(*reason);
    return std::get<AvFunctions>(loaded);
}

}  // namespace collidescope::replays
