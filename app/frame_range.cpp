// Parsing `--frames`.

#include "frame_range.hpp"

#include "collidescope/error.hpp"

#include <charconv>
#include <optional>
#include <string>

namespace collidescope::app {
namespace {

[[noreturn]] void fail(std::string_view spec, const std::string& what) {
    throw InputError("--frames '" + std::string(spec) + "': " + what);
}

// A frame number, or nothing for an empty field; throws on anything else.
std::optional<std::uint64_t> parse_bound(std::string_view field, std::string_view spec) {
    if (field.empty()) return std::nullopt;
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size()) {
        fail(spec, "expected A:B, A:, :B or N with frame numbers >= 0");
    }
    return value;
}

}  // namespace

FrameRange parse_frame_range(std::string_view spec, std::uint32_t frame_count) {
    if (frame_count == 0) fail(spec, "the scene has no frames");
    // 64-bit bounds: N + 1 and any number a user types stay representable.
    std::uint64_t begin = 0;
    std::uint64_t end = frame_count;
    const std::size_t colon = spec.find(':');
    if (colon == std::string_view::npos) {
        if (const std::optional<std::uint64_t> frame = parse_bound(spec, spec)) {
            begin = *frame;
            end = *frame + 1;
        }
    } else {
        begin = parse_bound(spec.substr(0, colon), spec).value_or(0);
        end = parse_bound(spec.substr(colon + 1), spec).value_or(frame_count);
    }
    if (begin >= frame_count || end > frame_count) {
        fail(spec, "out of range (the scene has " + std::to_string(frame_count) + " frames, 0.." +
                       std::to_string(frame_count - 1) + ")");
    }
    if (begin >= end) fail(spec, "empty range (A:B is half-open: frames A to B-1)");
    return {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
}

}  // namespace collidescope::app
