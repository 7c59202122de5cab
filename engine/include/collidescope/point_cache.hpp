#pragma once
/// Point caches: one mesh's vertex positions over many frames (engine/src/mesh).
///
/// Two formats, chosen by extension (docs/how-to/point-caches.md):
/// - PC2 (`.pc2`, POINTCACHE2, written by 3ds Max and Blender): a little-endian 32-byte header
///   "POINTCACHE2\0", int32 version (1), int32 point count, float32 start frame, float32
///   sample rate (frames between samples), int32 sample count; then float32 x y z per point
///   per sample.
/// - MDD (`.mdd`, LightWave and Blender): big-endian int32 frame count, int32 point count,
///   float32 time in seconds per frame, then float32 x y z per point per frame.
/// The header is checked against the file's size before anything is allocated, and frames are
/// read one at a time (seek and read), so a large cache never sits in memory whole.

#include "collidescope/types.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace collidescope {

/// What a cache's header says, checked against the file: where the frames lie and their times.
struct PointCacheLayout {
    std::uint32_t frame_count = 0;   ///< at least 1
    std::uint32_t point_count = 0;   ///< at least 1
    std::uint64_t data_offset = 0;   ///< byte offset of frame 0's first coordinate
    bool big_endian = false;         ///< byte order of the float32 coordinates
    /// frame_times[k]: frame k's time in seconds from frame 0 (size frame_count). PC2 counts
    /// in frames, converted at k_pc2_frame_rate; MDD stores seconds.
    std::vector<double> frame_times;
    double fps = 0;  ///< frames per second the times imply; 0 when they do not say (one frame)
};

/// PC2 stores times in frames of the exporting application's frame rate, which the file does
/// not record; collidescope reads them at this rate (frames per second).
inline constexpr double k_pc2_frame_rate = 30.0;

/// True when `file`'s extension (any case) is a point cache's: .pc2 or .mdd.
bool is_point_cache_file(const std::filesystem::path& file);

/// A point cache opened for reading one frame at a time. Not thread-safe (one file position).
class PointCacheReader {
public:
    /// Opens `file` (.pc2 or .mdd, by extension) and checks its header against the file's size.
    /// Throws InputError naming the file and the field (missing file, wrong magic, a count
    /// the file's size does not match, a non-finite or decreasing time).
    explicit PointCacheReader(const std::filesystem::path& file);

    const std::filesystem::path& file() const { return m_file; }
    const PointCacheLayout& layout() const { return m_layout; }

    /// Frame `frame`'s positions (layout().point_count of them, exactly the file's float32
    /// values). Throws InputError naming the file, frame and vertex on a non-finite coordinate,
    /// and the file on a read failure; std::out_of_range when frame >= frame_count.
    std::vector<Vec3> read_frame(std::uint32_t frame);

private:
    struct FileCloser {
        void operator()(std::FILE* stream) const { std::fclose(stream); }
    };

    std::filesystem::path m_file;
    std::unique_ptr<std::FILE, FileCloser> m_stream;
    PointCacheLayout m_layout;
    std::vector<float> m_buffer;  ///< one frame's raw coordinates, reused
};

}  // namespace collidescope
