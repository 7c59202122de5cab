// encode_pngs_as_video(): a clip from PNGs already written, in order (the last step of a
// frame-parallel replay --video, app/replay_command.cpp). The PNGs hold the RGBA pixels replay()
// hands its encoder, losslessly, so the encoder sees the same frames.

#include "collidescope/replays/replay.hpp"

#include "replay_common.hpp"
#include "open_video.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <stb_image.h>

#include <chrono>
#include <cstdlib>
#include <memory>

namespace collidescope::replays {
namespace {

// The RGBA pixels of `file`, which must be width x height. Throws InputError naming it.
std::vector<std::uint8_t> read_png(const std::filesystem::path& file, int width, int height) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(file.c_str(), &w, &h, &channels, 4);
    if (pixels == nullptr) throw InputError(file.string() + ": cannot read the PNG (" + stbi_failure_reason() + ")");
    const std::unique_ptr<stbi_uc, void (*)(void*)> owned(pixels, stbi_image_free);
    if (w != width || h != height) {
        throw InputError(file.string() + ": " + std::to_string(w) + "x" + std::to_string(h) + " pixels, not the clip's " +
                         std::to_string(width) + "x" + std::to_string(height));
    }
    return {pixels, pixels + std::size_t(w) * std::size_t(h) * 4};
}

}  // namespace

ReplaySummary encode_pngs_as_video(const std::filesystem::path& recording, const std::vector<std::filesystem::path>& pngs,
                                   const ReplayOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    VideoSettings settings;
    settings.path = options.video;
    settings.width = options.width;
    settings.height = options.height;
    settings.fps = clip_fps(recorder::Recording(recording));
    const std::unique_ptr<VideoEncoder> video = open_video(settings);
    for (const std::filesystem::path& png : pngs) video->add_frame(read_png(png, options.width, options.height));
    video->finish();
    ReplaySummary summary;
    summary.frames = pngs.size();
    summary.video = options.video;
    summary.video_fps = settings.fps;
    summary.video_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

}  // namespace collidescope::replays
