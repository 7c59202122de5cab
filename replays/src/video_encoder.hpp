#pragma once
// Video out (replays/src, private): the replayed frames as one clip, through FFmpeg's libraries
// (libavcodec, libavformat, libswscale; libavfilter for the GIF palette), never a subprocess.
// The file's extension picks the backend: .mp4 is H.264 (h264_video.cpp), .gif an animated
// GIF (gif_video.cpp). docs/how-to/replay.md, "Video".
//
// Frames go in in order. The clip is written under a temporary name beside the target and
// renamed onto it by finish(), so a failed or interrupted replay leaves no half-written file.
// open_video.hpp opens one; video_backends.hpp declares the backends.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace collidescope::replays {

/// What a clip is made of.
struct VideoSettings {
    std::filesystem::path path;  ///< the clip to write (.mp4 or .gif)
    int width = 0;               ///< of the frames fed in, pixels
    int height = 0;
    double fps = 30;             ///< frames per second of the clip (> 0)
    /// x264's speed/size trade-off (its --preset) for .mp4; bench/micro/bench_video_encode.cpp and
    /// records/video-encoding.md compare them.
    std::string h264_preset = "veryfast";
};

/// Encodes RGBA frames into a clip. Not thread-safe: one caller at a time.
class VideoEncoder {
public:
    virtual ~VideoEncoder() = default;
    /// Adds the next frame: width * height RGBA pixels, top row first. Throws InputError
    /// naming the file when encoding or writing fails.
    virtual void add_frame(std::span<const std::uint8_t> rgba) = 0;
    /// Flushes the encoder, completes the file and moves it onto its name. Throws InputError
    /// naming the file. Without finish(), the destructor removes what was written.
    virtual void finish() = 0;
    /// Frames added so far.
    virtual std::uint64_t frames() const = 0;
};

}  // namespace collidescope::replays
