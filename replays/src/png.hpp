#pragma once
// PNG files through stb_image_write (replays/src, private), compressed with zlib.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace collidescope::replays {

/// Writes an RGBA image (top row first) as a PNG. The bytes depend only on the pixels.
/// Throws InputError naming the file when it cannot be written.
void write_png(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgba, int width, int height);

/// The pixels of an RGBA image (width wide, top row first) inside x, y, w, h.
std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& rgba, int width, int x, int y, int w, int h);

/// Box-filters an RGBA image down to `width` x `height` (for the contact sheet).
std::vector<std::uint8_t> downscale(const std::vector<std::uint8_t>& rgba, int from_width, int from_height, int width,
                                    int height);

}  // namespace collidescope::replays
