#pragma once
// Helpers of the replayer's tests: recordings made by the built `collidescope record`, PNGs
// decoded with stb_image, colour classes of the replay's palette, planting a pair difference.

#include "collidescope/replays/camera.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::testing {

/// A decoded PNG, RGBA, top row first.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* at(int x, int y) const { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

/// Decodes a PNG; width 0 when it does not decode.
Image read_png(const std::filesystem::path& file);
/// The bytes of a file.
std::string read_bytes(const std::filesystem::path& file);

/// The replay's collision colour after lighting: strongly red.
bool is_collision_colour(const std::uint8_t* p);
/// The --diff highlight after lighting: strongly green.
bool is_diff_colour(const std::uint8_t* p);
/// The background the replay clears to.
bool is_background(const std::uint8_t* p);
/// Text-like: bright and grey (ImGui's text colour over a dark panel).
bool is_bright(const std::uint8_t* p);

/// Pixels of `image` in `rect` for which `test` holds.
template <class Test>
std::uint64_t count_pixels(const Image& image, const replays::Rect& rect, Test test) {
    std::uint64_t count = 0;
    for (int y = rect.y; y < rect.y + rect.h && y < image.height; ++y) {
        for (int x = rect.x; x < rect.x + rect.w && x < image.width; ++x) count += test(image.at(x, y)) ? 1 : 0;
    }
    return count;
}

/// Records `scene` (NAME[:PRESET]) with `method` into `file` with the built binary; extra
/// arguments appended. Fails the test when recording fails.
void record(const std::string& scene, const std::string& method, const std::filesystem::path& file,
            const std::vector<std::string>& extra = {});

/// Overwrites element (row, column) of the 2-D uint32 dataset /collisions/pairs.
void overwrite_pair_element(const std::filesystem::path& file, std::uint64_t row, int column, std::uint32_t value);

/// Adds the root attributes `fps` and `up_axis` (schema 1.4) to a recording of an untimed
/// scene, as `record` writes them for an animated model's.
void set_time_attributes(const std::filesystem::path& file, double fps, char up_axis);

/// Adds /frames/time (seconds, one per recorded frame, unit "s") to a recording, without `fps`:
/// a point cache's times without a rate.
void add_frame_times(const std::filesystem::path& file, const std::vector<double>& times);

/// A fresh directory for one test.
std::filesystem::path test_dir(const std::string& name);

}  // namespace collidescope::testing
