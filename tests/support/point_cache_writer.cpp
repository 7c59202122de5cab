// PC2 and MDD writers for tests.

#include "support/point_cache_writer.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace collidescope::testing {
namespace {

class Bytes {
public:
    explicit Bytes(bool big_endian) : m_big_endian(big_endian) {}

    template <class T>
    void put(T value) {
        static_assert(sizeof(T) == 4);
        auto bits = std::bit_cast<std::uint32_t>(value);
        if (m_big_endian != (std::endian::native == std::endian::big)) bits = __builtin_bswap32(bits);
        char raw[4];
        std::memcpy(raw, &bits, 4);
        m_bytes.append(raw, 4);
    }
    void text(const char* data, std::size_t size) { m_bytes.append(data, size); }
    void frames(const PositionFrames& frames) {
        for (const std::vector<Vec3>& frame : frames) {
            for (const Vec3& v : frame) {
                for (int axis = 0; axis < 3; ++axis) put(static_cast<float>(v[axis]));
            }
        }
    }
    void save(const std::filesystem::path& file) const {
        std::ofstream out(file, std::ios::binary);
        out.write(m_bytes.data(), static_cast<std::streamsize>(m_bytes.size()));
        if (!out) throw std::runtime_error(file.string() + ": cannot write");
    }

private:
    bool m_big_endian;
    std::string m_bytes;
};

std::int32_t point_count(const PositionFrames& frames) {
    return frames.empty() ? 0 : static_cast<std::int32_t>(frames.front().size());
}

}  // namespace

void write_pc2(const std::filesystem::path& file, const PositionFrames& frames, float start_frame,
               float sample_rate) {
    Bytes bytes(false);
    bytes.text("POINTCACHE2", 12);  // with its terminating '\0'
    bytes.put(std::int32_t{1});
    bytes.put(point_count(frames));
    bytes.put(start_frame);
    bytes.put(sample_rate);
    bytes.put(static_cast<std::int32_t>(frames.size()));
    bytes.frames(frames);
    bytes.save(file);
}

void write_mdd(const std::filesystem::path& file, const PositionFrames& frames,
               const std::vector<float>& times) {
    Bytes bytes(true);
    bytes.put(static_cast<std::int32_t>(frames.size()));
    bytes.put(point_count(frames));
    for (const float time : times) bytes.put(time);
    bytes.frames(frames);
    bytes.save(file);
}

}  // namespace collidescope::testing
