// PointCacheReader: a PC2 or MDD file's header checked against its size, then one frame at a
// time by seek and read.

#include "mesh/point_cache_format.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace collidescope {
namespace point_cache {

void fail(const CacheFile& file, const std::string& what) {
    throw InputError(file.source + ": " + what);
}

void read_bytes(const CacheFile& file, std::uint64_t offset, std::span<std::byte> out,
                std::string_view what) {
    if (offset > file.size || out.size() > file.size - offset) {
        fail(file, std::string(what) + ": file truncated: expected " + std::to_string(out.size()) +
                       " bytes at byte " + std::to_string(offset) + ", the file ends at byte " +
                       std::to_string(file.size));
    }
    if (fseeko(file.stream, static_cast<off_t>(offset), SEEK_SET) != 0 ||
        std::fread(out.data(), 1, out.size(), file.stream) != out.size()) {
        fail(file, std::string(what) + ": read error at byte " + std::to_string(offset) + " (" +
                       (std::ferror(file.stream) ? std::strerror(errno) : "unexpected end of file") + ")");
    }
}

void check_data_size(const CacheFile& file, std::uint64_t data_offset, std::uint64_t frames,
                     std::uint64_t points, std::string_view frames_word) {
    // frames and points are below 2^31: frames * points fits, * 12 may not.
    const std::uint64_t coordinates = frames * points;
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const bool fits = coordinates <= (max - data_offset) / 12;
    const std::uint64_t needed = fits ? data_offset + coordinates * 12 : max;
    if (needed == file.size) return;
    const std::string counts = "header: " + std::to_string(frames) + " " + std::string(frames_word) +
                               " x " + std::to_string(points) + " points need ";
    const std::string need = fits ? std::to_string(needed) + " bytes" : "more than 2^64 bytes";
    const std::string verdict = needed > file.size ? "truncated, or the header's counts are wrong"
                                                   : "the header's counts are wrong";
    fail(file, counts + need + ", the file has " + std::to_string(file.size) + " (" + verdict + ")");
}

}  // namespace point_cache

namespace {

std::string lowercase_extension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

bool is_point_cache_file(const std::filesystem::path& file) {
    const std::string extension = lowercase_extension(file);
    return extension == ".pc2" || extension == ".mdd";
}

PointCacheReader::PointCacheReader(const std::filesystem::path& file) : m_file(file) {
    const std::string source = file.string();
    const std::string extension = lowercase_extension(file);
    if (extension != ".pc2" && extension != ".mdd") {
        throw InputError(source + ": not a point cache (expected a .pc2 or .mdd file)");
    }
    std::error_code error;
    const auto status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status)) throw InputError(source + ": no such file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(source + ": not a regular file");
    const std::uint64_t size = std::filesystem::file_size(file, error);
    if (error) throw InputError(source + ": cannot read its size (" + error.message() + ")");
    m_stream.reset(std::fopen(file.c_str(), "rb"));
    if (!m_stream) throw InputError(source + ": cannot open (" + std::strerror(errno) + ")");
    const point_cache::CacheFile cache{m_stream.get(), size, source};
    m_layout = extension == ".pc2" ? point_cache::read_pc2_layout(cache)
                                   : point_cache::read_mdd_layout(cache);
}

std::vector<Vec3> PointCacheReader::read_frame(std::uint32_t frame) {
    if (frame >= m_layout.frame_count) {
        throw std::out_of_range(m_file.string() + ": frame " + std::to_string(frame) + " of " +
                                std::to_string(m_layout.frame_count));
    }
    const std::size_t points = m_layout.point_count;
    const std::uint64_t frame_bytes = std::uint64_t{points} * 12;
    m_buffer.resize(points * 3);
    const point_cache::CacheFile cache{m_stream.get(), m_layout.data_offset + m_layout.frame_count * frame_bytes,
                                       m_file.string()};
    const std::span<std::byte> raw(reinterpret_cast<std::byte*>(m_buffer.data()), frame_bytes);
    read_bytes(cache, m_layout.data_offset + frame * frame_bytes, raw, "frame " + std::to_string(frame));

    std::vector<Vec3> vertices(points);
    for (std::size_t v = 0; v < points; ++v) {
        for (int axis = 0; axis < 3; ++axis) {
            const float value = point_cache::load4<float>(&raw[(v * 3 + axis) * 4], m_layout.big_endian);
            if (!std::isfinite(value)) {
                point_cache::fail(cache, "frame " + std::to_string(frame) + ", vertex " + std::to_string(v) +
                                             ": coordinate " + "xyz"[axis] + " is not finite (" +
                                             std::to_string(value) + ")");
            }
            vertices[v][axis] = value;
        }
    }
    return vertices;
}

}  // namespace collidescope
