#pragma once
// Steps replay() and replay_diff() share (replays/src, private).

#include "frame_data.hpp"
#include "overlay.hpp"

#include "collidescope/replays/options.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace collidescope::replays {

/// Creates `dir` when missing. Throws InputError naming it when that fails.
void prepare_output_dir(const std::filesystem::path& dir);
/// The rows of `data` in the options' frame range. Throws InputError naming the file when none.
std::vector<std::uint64_t> replay_rows(const RecordingData& data, const ReplayOptions& options);
/// `camera` with its up axis resolved: --up when given, else the recording's `up_axis`, else z.
CameraSpec resolved_camera(const CameraSpec& camera, const RecordingData& data);
/// The clip's frame rate: the recording's `fps`; else, when it has frame times (a point cache
/// with times but no rate), one over the median step between them; else 30.
double clip_fps(const recorder::Recording& recording);
/// The session's annotations; points into `data`.
SessionView session_view(const RecordingData& data);

}  // namespace collidescope::replays
