#pragma once
// The video backends behind open_video() (replays/src, private): one per container.

#include "video_encoder.hpp"

#include <memory>

namespace collidescope::replays {

/// H.264 (libx264), yuv420p, in MP4 with faststart (h264_video.cpp).
std::unique_ptr<VideoEncoder> open_h264_video(const VideoSettings& settings);
/// Animated GIF, a palette per frame (gif_video.cpp).
std::unique_ptr<VideoEncoder> open_gif_video(const VideoSettings& settings);

}  // namespace collidescope::replays
