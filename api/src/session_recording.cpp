// start_recording: the session's SessionInfo and the recorder.

#include "session_recording.hpp"

namespace collidescope::api {

std::unique_ptr<recorder::Recorder> start_recording(const SessionOptions& options, const PipelineConfig& config,
                                                    std::vector<std::string> object_names, const Frame& first_frame) {
    recorder::SessionInfo info;
    info.scene = options.scene;
    info.method = config.method;
    info.self_collision = config.self_collision;
    info.threads = config.threads;
    info.frame_begin = 0;
    info.frame_end = 0;  // open-ended: the caller's loop decides
    info.depth_image_pixels = std::uint64_t(config.gpu.resolution) * std::uint64_t(config.gpu.resolution);
    info.tool_version = COLLIDESCOPE_VERSION;
    info.git_revision = COLLIDESCOPE_GIT_REVISION;
    info.object_names = std::move(object_names);
    info.regions = options.regions;
    recorder::RecorderConfig recorder_config;
    recorder_config.path = options.record;
    return std::make_unique<recorder::Recorder>(recorder_config, std::move(info), first_frame);
}

}  // namespace collidescope::api
