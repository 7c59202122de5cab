#pragma once
// Frame patterns: `cloth.%04d.ply`, `cloth.%d.ply` or `cloth.####.obj` (engine/src/scene, private).
//
// `%0Nd` and a run of N `#` both mean "the frame number, zero-padded to N digits" (more digits
// when the number needs them), `%d` the number without padding. A file matches when its name
// is exactly what printf would write for some number, so `cloth.%04d.ply` matches
// cloth.0007.ply and cloth.12345.ply but not cloth.007.ply.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace collidescope {

/// A file name with one frame number field, split around the field.
struct FramePattern {
    std::filesystem::path directory;  ///< where the frames live ("" for the working directory)
    std::string prefix;               ///< file name text before the field
    std::string suffix;               ///< file name text after the field
    int width = 0;                    ///< minimum digits, zero-padded (0 for %d)

    /// The file name of frame number `number`.
    std::string file_name(std::uint64_t number) const;
    /// The frame number `name` encodes, or nothing when it does not match.
    std::optional<std::uint64_t> match(const std::string& name) const;
};

/// Splits `spec` into a pattern when its file name holds one frame number field; nothing when
/// it holds none. Throws InputError naming `spec` when it holds more than one.
std::optional<FramePattern> parse_frame_pattern(const std::string& spec);

/// The frame files that exist, from the lowest matching number to the highest. Throws
/// InputError naming `spec` when no file matches, and naming the first missing file when the
/// numbers have a gap (a gap would otherwise drop every frame after it without a word).
std::vector<std::filesystem::path> expand_frame_pattern(const FramePattern& pattern,
                                                        const std::string& spec);

/// An object's name from a file or pattern name: the name without the number field, the
/// extension (and .gz) and the separators left at its ends ("cloth.%04d.ply" -> "cloth").
std::string object_name_from(const std::string& file_name);

}  // namespace collidescope
