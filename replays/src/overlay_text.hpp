#pragma once
// The overlay's lines of text, apart from their drawing (overlay_frame.cpp), so that what a
// frame shows is testable: a value the recording lacks for a frame (NaN: the decision's GPU
// time on a frame that never ran the GPU, the AABB details of a GPU frame) reads "not run" or
// the line is left out, never "nan".

#include "frame_data.hpp"

#include <optional>
#include <string>
#include <vector>

namespace collidescope::replays {

/// `pattern` (one printf conversion of a double) applied to `value`, or `missing` when it is
/// not finite.
std::string measured(const char* pattern, double value, const char* missing = "not run");

/// The decision panel's lines (thesis 4.4): what ran and why, AABB_T / GPU_T / hybrid times,
/// the rebuild average and policy, exploration and draw. One line saying so when the
/// recording has no decision for the frame.
std::vector<std::string> decision_text(const FrameData& frame);

/// "AABB: rebuilt N (reasons), tree quality Q", or nothing when the frame ran no AABB trees.
std::optional<std::string> aabb_text(const FrameData& frame);

/// "hybrid: TRI_1 .. TRI_R .. TRI_2 ..", or nothing when the frame ran no hybrid framework.
std::optional<std::string> hybrid_text(const FrameData& frame);

/// "queries N   P N tris/query   O T ms" of a frame that ran the GPU cull.
std::string gpu_queries_text(const FrameData& frame);

}  // namespace collidescope::replays
