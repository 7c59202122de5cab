#pragma once
// Opening a clip (replays/src, private): the backend by the file's extension
// (video_backends.hpp), behind the VideoEncoder interface (video_encoder.hpp).

#include "video_encoder.hpp"

#include "collidescope/replays/replay.hpp"  // check_video_path

#include <memory>

namespace collidescope::replays {

/// Opens the clip `settings.path` for writing (its backend by extension). Throws InputError
/// naming the file (unknown extension, unwritable directory) or UnavailableError when this
/// FFmpeg lacks the encoder (libx264, gif) or filters (palettegen, paletteuse).
std::unique_ptr<VideoEncoder> open_video(const VideoSettings& settings);

}  // namespace collidescope::replays
