// PC2 (POINTCACHE2) headers: what 3ds Max's Point Cache 2 and Blender's exporter write.
//
//   char[12] "POINTCACHE2\0" | int32 version = 1 | int32 points | float32 start frame
//   | float32 sample rate | int32 samples        (32 bytes, little-endian)
//   then samples x points x float32 {x, y, z}
//
// The sample rate is the number of the application's frames between two samples (1 samples
// every frame); the application's frame rate is not stored, so times are read at
// k_pc2_frame_rate frames per second (docs/how-to/point-caches.md).

#include "mesh/point_cache_format.hpp"

#include <array>
#include <cmath>

namespace collidescope::point_cache {
namespace {

constexpr std::size_t k_header_size = 32;
constexpr char k_magic[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};

}  // namespace

PointCacheLayout read_pc2_layout(const CacheFile& file) {
    if (file.size < k_header_size) {
        fail(file, "file truncated: a PC2 header needs 32 bytes, the file has " + std::to_string(file.size));
    }
    std::array<std::byte, k_header_size> header;
    read_bytes(file, 0, header, "header");
    if (std::memcmp(header.data(), k_magic, sizeof k_magic) != 0) {
        fail(file, "not a PC2 file (no 'POINTCACHE2' magic at byte 0)");
    }
    const auto version = load4<std::int32_t>(&header[12], false);
    const auto points = load4<std::int32_t>(&header[16], false);
    const auto start_frame = load4<float>(&header[20], false);
    const auto sample_rate = load4<float>(&header[24], false);
    const auto samples = load4<std::int32_t>(&header[28], false);
    if (version != 1) fail(file, "header: version " + std::to_string(version) + " (only version 1 is known)");
    if (points <= 0) fail(file, "header: point count " + std::to_string(points) + " (expected at least 1)");
    if (samples <= 0) fail(file, "header: sample count " + std::to_string(samples) + " (expected at least 1)");
    if (!std::isfinite(start_frame)) fail(file, "header: start frame is not finite (" + header_number(start_frame) + ")");
    if (!(std::isfinite(sample_rate) && sample_rate > 0)) {
        fail(file, "header: sample rate " + header_number(sample_rate) + " (expected a positive number of frames)");
    }
    check_data_size(file, k_header_size, static_cast<std::uint64_t>(samples),
                    static_cast<std::uint64_t>(points), "samples");

    PointCacheLayout layout;
    layout.frame_count = static_cast<std::uint32_t>(samples);
    layout.point_count = static_cast<std::uint32_t>(points);
    layout.data_offset = k_header_size;
    layout.big_endian = false;
    layout.frame_times.resize(layout.frame_count);
    for (std::uint32_t k = 0; k < layout.frame_count; ++k) {
        layout.frame_times[k] = k * double{sample_rate} / k_pc2_frame_rate;
    }
    layout.fps = k_pc2_frame_rate / double{sample_rate};
    return layout;
}

}  // namespace collidescope::point_cache
