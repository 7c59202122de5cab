#pragma once
// Decoding a clip back with libavformat and libavcodec (the replayer's video tests): frame
// count, size, codec, frame rate, and every frame as RGBA.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::testing {

struct DecodedVideo {
    bool opened = false;        ///< false: `error` says why
    std::string error;
    std::string codec;          ///< libavcodec's name ("h264", "gif")
    std::string pixel_format;   ///< of the coded frames ("yuv420p", "pal8", "bgra")
    std::string profile;        ///< "High", "Main", ... ("" when the codec has none)
    int width = 0;
    int height = 0;
    double fps = 0;             ///< the stream's average frame rate
    std::uint64_t frames = 0;   ///< frames decoded
    std::vector<std::vector<std::uint8_t>> rgba;  ///< every frame in order, width * height RGBA each
};

/// Decodes every frame of the first video stream of `file`.
DecodedVideo decode_video(const std::filesystem::path& file);

/// Mean absolute difference over the R, G and B of two equal-sized RGBA images (0-255).
double mean_rgb_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);

/// For each decoded frame, the index of the image in `images` closest to it (mean_rgb_difference),
/// and that difference: a clip of the replayed frames maps frame k to image k, and a frozen or
/// repeated frame maps to an earlier one.
struct FrameMatch {
    std::size_t closest = 0;
    double difference = 0;
};
std::vector<FrameMatch> match_frames(const DecodedVideo& video, const std::vector<std::vector<std::uint8_t>>& images);

}  // namespace collidescope::testing
