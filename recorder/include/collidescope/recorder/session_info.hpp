#pragma once
/// The session a recording comes from: what the file's root attributes say (written by the
/// recorder, recorder.hpp; docs/reference/recording.md).

#include <cstdint>
#include <string>
#include <vector>

namespace collidescope::recorder {

/// What the file's root attributes say about the session.
struct SessionInfo {
    std::string scene;                      ///< scene name (built-in name or input summary)
    std::string preset;                     ///< generator preset ("" for files)
    std::uint64_t seed = 0;                 ///< generator seed (0 for files)
    std::string method;                     ///< method requested
    bool self_collision = false;
    int threads = 0;                        ///< requested worker threads (0 = all hardware threads)
    std::uint32_t frame_begin = 0;          ///< first scene frame recorded
    std::uint32_t frame_end = 0;            ///< one past the last scene frame to record
    std::string depth = "off";              ///< --depth: "off" or "every:N" (nothing to record before Mode 2)
    std::string gl_renderer;                ///< GL_RENDERER of the cull's context ("" without GPU cull)
    bool regions = false;                   ///< record --regions: /regions per frame (schema 1.5)
    /// record --between-frames: /intervals, each frame with the one before it (schema 1.7).
    bool between_frames = false;
    double ccd_tolerance = 0;               ///< --ccd-tolerance (0: automatic)
    /// Pixels of one depth image (the cull's resolution squared): the depth pixels' chunk, so
    /// each image is one chunk, written once. 0: 65536.
    std::uint64_t depth_image_pixels = 0;
    std::string tool_version;               ///< COLLIDESCOPE_VERSION
    std::string git_revision;               ///< COLLIDESCOPE_GIT_REVISION
    std::vector<std::string> object_names;  ///< in input order
    // What the inputs say about time (Scene::frame_times, fps, clip, up_axis): written only
    // when present (schema 1.4), so recordings of untimed scenes stay as they were.
    /// Seconds of every scene frame, indexed by scene frame number (size >= frame_end), or empty.
    std::vector<double> frame_times;
    double fps = 0;                         ///< 0 = unknown (no `fps` attribute)
    std::string clip;                       ///< "" = none (no `clip` attribute)
    char up_axis = 0;                       ///< 'x', 'y', 'z'; 0 = unknown (no `up_axis` attribute)
};

}  // namespace collidescope::recorder
