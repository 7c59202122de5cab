#pragma once
// `--frames A:B`: which frames a subcommand processes.
//
// Half-open, like Python slices, frames numbered from 0 in scene order (for a frame pattern,
// frame 0 is the first file that exists, whatever number its name holds): `A:B` is frames
// A .. B-1, `A:` from A to the end, `:B` frames 0 .. B-1, `N` frame N alone, `:` or nothing
// every frame. A range that is empty or reaches past the last frame is an error.

#include <cstdint>
#include <string_view>

namespace collidescope::app {

/// Frames [begin, end).
struct FrameRange {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
};

/// Parses `spec` against a scene of `frame_count` frames ("" means every frame). Throws
/// InputError naming the spec on bad syntax, an empty range or one out of range.
FrameRange parse_frame_range(std::string_view spec, std::uint32_t frame_count);

}  // namespace collidescope::app
