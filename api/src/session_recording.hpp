#pragma once
// A session's recording: the recorder `collidescope record` uses, described as a session
// (scene name, method, objects), started at the first frame, which sizes its chunks.

#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/recorder.hpp"
#include "collidescope/session.hpp"

#include <memory>
#include <string>
#include <vector>

namespace collidescope::api {

/// Creates options.record and returns its recorder, which the pipeline reports to. The frames
/// are open-ended, so the file's frame_end attribute is 0 (docs/reference/recording.md). Throws
/// InputError naming the file when it cannot be created.
std::unique_ptr<recorder::Recorder> start_recording(const SessionOptions& options, const PipelineConfig& config,
                                                    std::vector<std::string> object_names, const Frame& first_frame);

}  // namespace collidescope::api
