// MDD headers: what LightWave and Blender's exporter write (big-endian throughout).
//
//   int32 frames | int32 points | float32 time[frames] (seconds)
//   then frames x points x float32 {x, y, z}

#include "mesh/point_cache_format.hpp"

#include <cmath>
#include <vector>

namespace collidescope::point_cache {
namespace {

constexpr std::uint64_t k_counts_size = 8;

// Times relative to frame 0; each finite and none before the one preceding it.
std::vector<double> frame_times(const CacheFile& file, std::uint32_t frames) {
    std::vector<std::byte> raw(std::size_t{frames} * 4);  // the size check bounds this by the file
    read_bytes(file, k_counts_size, raw, "frame times");
    std::vector<double> times(frames);
    double first = 0;
    for (std::uint32_t k = 0; k < frames; ++k) {
        const double time = load4<float>(&raw[std::size_t{k} * 4], true);
        if (!std::isfinite(time)) {
            fail(file, "time of frame " + std::to_string(k) + " is not finite (" + header_number(time) + ")");
        }
        if (k == 0) first = time;
        times[k] = time - first;
        if (k > 0 && times[k] < times[k - 1]) {
            fail(file, "time of frame " + std::to_string(k) + " (" + header_number(time) +
                           " s) is before frame " + std::to_string(k - 1) + "'s (" +
                           header_number(times[k - 1] + first) + " s)");
        }
    }
    return times;
}

}  // namespace

PointCacheLayout read_mdd_layout(const CacheFile& file) {
    if (file.size < k_counts_size) {
        fail(file, "file truncated: an MDD header needs at least 8 bytes, the file has " + std::to_string(file.size));
    }
    std::byte counts[k_counts_size];
    read_bytes(file, 0, counts, "header");
    const auto frames = load4<std::int32_t>(&counts[0], true);
    const auto points = load4<std::int32_t>(&counts[4], true);
    if (frames <= 0) fail(file, "header: frame count " + std::to_string(frames) + " (expected at least 1)");
    if (points <= 0) fail(file, "header: point count " + std::to_string(points) + " (expected at least 1)");
    const std::uint64_t data_offset = k_counts_size + 4 * static_cast<std::uint64_t>(frames);
    check_data_size(file, data_offset, static_cast<std::uint64_t>(frames),
                    static_cast<std::uint64_t>(points), "frames");

    PointCacheLayout layout;
    layout.frame_count = static_cast<std::uint32_t>(frames);
    layout.point_count = static_cast<std::uint32_t>(points);
    layout.data_offset = data_offset;
    layout.big_endian = true;
    layout.frame_times = frame_times(file, layout.frame_count);
    const double span = layout.frame_times.back();
    if (layout.frame_count > 1 && span > 0) layout.fps = (layout.frame_count - 1) / span;
    return layout;
}

}  // namespace collidescope::point_cache
