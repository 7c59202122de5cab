#pragma once
/// The replayer: a recording (recorder/, docs/reference/recording.md) -> one annotated PNG per frame,
/// rendered offscreen through the engine's GL context interface (OSMesa), several frames at
/// once in several threads, each with its own context. docs/how-to/replay.md says what a frame shows.

#include "collidescope/replays/options.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace collidescope::replays {

/// Called after each frame is written, from the thread that wrote it, one call at a time, with
/// the number of images the run writes (for a progress bar: its frames, and its moments of
/// contact with ReplayOptions::contact_moments).
using FrameDone = std::function<void(std::uint64_t total)>;

/// What a replay did.
struct ReplaySummary {
    std::uint64_t frames = 0;             ///< frames rendered (PNGs written, when asked for)
    std::vector<std::filesystem::path> files;  ///< the PNGs, in frame order (empty without output_dir)
    std::filesystem::path video;          ///< the clip written ("" when none was asked for)
    double video_fps = 0;                 ///< its frame rate
    double video_seconds = 0;             ///< seconds spent encoding it (thread seconds, within `seconds`)
    std::filesystem::path contact_sheet;  ///< "" when none was asked for
    /// ReplayOptions::contact_moments: the moment-of-contact PNGs written, in frame order.
    std::vector<std::filesystem::path> moment_files;
    double seconds = 0;                   ///< wall time of the rendering (after reading the metadata)
    int threads = 0;                      ///< render threads used
    std::uint64_t triangles = 0;          ///< triangles of the first replayed frame
    std::string renderer;                 ///< GL_RENDERER
    /// Seconds per step, summed over the render threads: reading the frame from the file (one
    /// thread at a time), issuing the GL draws and the overlay, reading the image back (where
    /// llvmpipe rasterises), encoding and writing the PNG.
    double read_seconds = 0;
    double draw_seconds = 0;
    double readback_seconds = 0;
    double png_seconds = 0;
    /// What the recording lacks that a layer would show ("no depth buffers in this recording", ...).
    std::vector<std::string> notes;
    /// --diff only: frames compared, and pairs found by only one of the two recordings.
    std::uint64_t only_in_a = 0;
    std::uint64_t only_in_b = 0;
};

/// Checks a clip's name for ReplayOptions::video: ".mp4" or ".gif" (any case), else throws
/// InputError naming the file and the formats known. Touches no file.
void check_video_path(const std::filesystem::path& path);

/// The scene frame numbers of the frames replay() would render for `options` (its frame
/// range, not its part), in order. Throws as replay() when there is none.
std::vector<std::uint32_t> replayed_frames(const std::filesystem::path& recording, const ReplayOptions& options);

/// The clip `options.video` of PNGs a replay wrote (`pngs`, in frame order, options.width x
/// options.height; e.g. the parts of a frame-parallel replay put together), at the recording's
/// frame rate: the clip replay() would have encoded from the same frames. Sets the summary's
/// video fields. Throws InputError naming a PNG that is missing, unreadable or of another size
/// (no clip is left), or as replay().
ReplaySummary encode_pngs_as_video(const std::filesystem::path& recording, const std::vector<std::filesystem::path>& pngs,
                                   const ReplayOptions& options);

/// Replays `recording` into `options.output_dir`/frame_NNNN.png (NNNN = the scene frame number)
/// and/or the clip `options.video`. Throws InputError naming the file (unreadable or corrupt
/// recording, no frame in range, unwritable output; a failed clip leaves no file) or
/// UnavailableError (no GL context, no H.264 encoder).
ReplaySummary replay(const std::filesystem::path& recording, const ReplayOptions& options,
                     const FrameDone& frame_done = {});

/// Renders the frames both recordings hold side by side (a left, b right) into
/// `options.output_dir`/diff_NNNN.png, the pairs each found that the other did not highlighted.
/// Frames are matched by scene frame number. Throws as replay().
ReplaySummary replay_diff(const std::filesystem::path& a, const std::filesystem::path& b,
                          const ReplayOptions& options, const FrameDone& frame_done = {});

}  // namespace collidescope::replays
