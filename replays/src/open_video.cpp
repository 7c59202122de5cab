// open_video(): the backend by the clip's extension.

#include "open_video.hpp"

#include "av_api.hpp"
#include "video_backends.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <cctype>

namespace collidescope::replays {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

void check_video_path(const std::filesystem::path& path) {
    const std::string extension = lower_extension(path);
    if (extension != ".mp4" && extension != ".gif") {
        throw InputError(path.string() + ": unknown video format '" + extension +
                         "' (--video writes .mp4, H.264, or .gif)");
    }
}

std::unique_ptr<VideoEncoder> open_video(const VideoSettings& settings) {
    check_video_path(settings.path);
    if (!(settings.fps > 0) || settings.fps > 1000) {
        throw InputError(settings.path.string() + ": frame rate " + std::to_string(settings.fps) + " out of range");
    }
    // The library never prints: FFmpeg's own log (libx264's statistics, muxer notes) is off;
    // every failure comes back as an error code and becomes an InputError naming the file.
    av().av_log_set_level(AV_LOG_QUIET);
    if (lower_extension(settings.path) == ".gif") return open_gif_video(settings);
    return open_h264_video(settings);
}

}  // namespace collidescope::replays
