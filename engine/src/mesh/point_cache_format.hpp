#pragma once
// The two point cache formats' headers (engine/src/mesh, private): pc2_reader.cpp and
// mdd_reader.cpp each turn a header into a PointCacheLayout; point_cache_reader.cpp reads the
// frames they locate.

#include "collidescope/point_cache.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

namespace collidescope::point_cache {

/// A header value as the readers' messages print it (%g).
inline std::string header_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// An open cache file: its stream, its size in bytes and its name for messages.
struct CacheFile {
    std::FILE* stream = nullptr;
    std::uint64_t size = 0;
    std::string source;
};

/// Throws InputError "SOURCE: WHAT".
[[noreturn]] void fail(const CacheFile& file, const std::string& what);

/// Reads exactly out.size() bytes at `offset`; throws InputError naming `what` when the file
/// ends first or the read fails.
void read_bytes(const CacheFile& file, std::uint64_t offset, std::span<std::byte> out,
                std::string_view what);

/// Checks that the frames the header declares fill the rest of the file exactly:
/// `data_offset` + frames * points * 12 == file size. Throws InputError naming the counts and
/// both sizes otherwise, before anything is allocated for them.
void check_data_size(const CacheFile& file, std::uint64_t data_offset, std::uint64_t frames,
                     std::uint64_t points, std::string_view frames_word);

/// A 4-byte value of type T stored at `p` in the given byte order.
template <class T>
T load4(const std::byte* p, bool big_endian) {
    static_assert(sizeof(T) == 4);
    std::uint32_t bits;
    std::memcpy(&bits, p, 4);
    if (big_endian != (std::endian::native == std::endian::big)) bits = __builtin_bswap32(bits);
    return std::bit_cast<T>(bits);
}

/// PC2: little-endian 32-byte header (POINTCACHE2).
PointCacheLayout read_pc2_layout(const CacheFile& file);

/// MDD: big-endian frame and point counts, then one time per frame.
PointCacheLayout read_mdd_layout(const CacheFile& file);

}  // namespace collidescope::point_cache
