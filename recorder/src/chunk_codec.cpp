// Shuffle + deflate, as HDF5's filters decode it, with incompressible byte planes stored.

#include "chunk_codec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include <zlib.h>

namespace collidescope::recorder {
namespace {

/// H5Z shuffle: byte b of element i goes to b * elements + i; leftover bytes stay at the end.
void shuffle(std::span<const std::byte> raw, std::size_t element_size, unsigned char* out) {
    const std::size_t elements = raw.size() / element_size;
    const auto* in = reinterpret_cast<const unsigned char*>(raw.data());
    if (element_size == 4) {  // float32 positions: the hot case, one pass
        unsigned char* p0 = out;
        unsigned char* p1 = out + elements;
        unsigned char* p2 = out + 2 * elements;
        unsigned char* p3 = out + 3 * elements;
        for (std::size_t i = 0; i < elements; ++i) {
            p0[i] = in[4 * i];
            p1[i] = in[4 * i + 1];
            p2[i] = in[4 * i + 2];
            p3[i] = in[4 * i + 3];
        }
    } else {
        for (std::size_t b = 0; b < element_size; ++b) {
            for (std::size_t i = 0; i < elements; ++i) out[b * elements + i] = in[i * element_size + b];
        }
    }
    const std::size_t whole = elements * element_size;
    if (raw.size() > whole) std::memcpy(out + whole, in + whole, raw.size() - whole);  // never with null
}

class Deflater {
public:
    explicit Deflater(int level) {
        if (deflateInit(&m_stream, level) != Z_OK) throw std::runtime_error("zlib: deflateInit failed");
        m_level = level;
    }
    ~Deflater() { deflateEnd(&m_stream); }
    Deflater(const Deflater&) = delete;
    Deflater& operator=(const Deflater&) = delete;

    /// Feeds `bytes` at `level` (0 = stored blocks) with `strategy`; `last` finishes the stream.
    void feed(const unsigned char* bytes, std::size_t size, int level, int strategy, bool last,
              std::vector<unsigned char>& out) {
        if (level != m_level || strategy != m_strategy) {
            // Compresses the input so far with the old level first (as deflate with Z_BLOCK).
            for (;;) {
                reserve(out);
                const int status = deflateParams(&m_stream, level, strategy);
                if (status == Z_OK) break;
                if (status != Z_BUF_ERROR) throw std::runtime_error("zlib: deflateParams failed");
                grow(out);
            }
            m_level = level;
            m_strategy = strategy;
        }
        m_stream.next_in = const_cast<unsigned char*>(bytes);  // zlib's API is not const-correct
        m_stream.avail_in = static_cast<uInt>(size);
        const int flush = last ? Z_FINISH : Z_NO_FLUSH;
        for (;;) {
            reserve(out);
            const int status = deflate(&m_stream, flush);
            if (status == Z_STREAM_END) break;
            if (status != Z_OK && status != Z_BUF_ERROR) throw std::runtime_error("zlib: deflate failed");
            if (!last && m_stream.avail_in == 0 && m_stream.avail_out > 0) break;
            if (m_stream.avail_out == 0) grow(out);
        }
    }
    std::size_t written() const { return m_stream.total_out; }

private:
    void reserve(std::vector<unsigned char>& out) {
        if (out.size() < m_stream.total_out + 1024) out.resize(std::max<std::size_t>(2 * out.size(), m_stream.total_out + 65536));
        m_stream.next_out = out.data() + m_stream.total_out;
        m_stream.avail_out = static_cast<uInt>(std::min<std::size_t>(out.size() - m_stream.total_out, 1u << 30));
    }
    void grow(std::vector<unsigned char>& out) {
        out.resize(2 * out.size() + 65536);
        reserve(out);
    }

    z_stream m_stream{};
    int m_level = -1;
    int m_strategy = Z_DEFAULT_STRATEGY;
};

}  // namespace

double sampled_entropy_bits(std::span<const unsigned char> bytes) {
    if (bytes.empty()) return 0.0;
    std::array<std::size_t, 256> histogram{};
    constexpr std::size_t k_runs = 16;
    constexpr std::size_t k_run = 256;
    std::size_t samples = 0;
    if (bytes.size() <= k_runs * k_run) {
        for (const unsigned char b : bytes) ++histogram[b];
        samples = bytes.size();
    } else {
        const std::size_t step = (bytes.size() - k_run) / (k_runs - 1);
        for (std::size_t r = 0; r < k_runs; ++r) {
            for (std::size_t i = 0; i < k_run; ++i) ++histogram[bytes[r * step + i]];
        }
        samples = k_runs * k_run;
    }
    double bits = 0.0;
    for (const std::size_t count : histogram) {
        if (count == 0) continue;
        const double p = static_cast<double>(count) / static_cast<double>(samples);
        bits -= p * std::log2(p);
    }
    return bits;
}

ChunkEncoding encode_shuffle_deflate(std::span<const std::byte> raw, std::size_t element_size, int level,
                                     std::vector<unsigned char>& out, std::size_t chunk_size) {
    if (chunk_size == 0) chunk_size = raw.size();
    if (element_size == 0 || level < 1 || level > 9 || chunk_size < raw.size()) {
        throw std::invalid_argument("encode_shuffle_deflate: bad arguments");
    }
    // Scratch for the shuffled chunk, kept per thread between chunks (the writer's one thread).
    thread_local std::vector<std::byte> padded;
    thread_local std::vector<unsigned char> shuffled;
    std::span<const std::byte> whole = raw;
    if (chunk_size > raw.size()) {
        padded.resize(chunk_size);
        if (!raw.empty()) std::memcpy(padded.data(), raw.data(), raw.size());  // raw.data() may be null
        std::memset(padded.data() + raw.size(), 0, chunk_size - raw.size());
        whole = padded;
    }
    shuffled.resize(chunk_size);
    shuffle(whole, element_size, shuffled.data());

    // Segments of the shuffled chunk, in order, each with its level: per plane the part that
    // came from `raw` (stored when its entropy says it will not compress), then its padding.
    struct Segment {
        std::size_t begin, size;
        int level;
        int strategy = Z_DEFAULT_STRATEGY;  ///< zero padding: Z_RLE, runs only, the fastest
    };
    std::vector<Segment> segments;
    ChunkEncoding encoding;
    const std::size_t elements = chunk_size / element_size;
    const std::size_t valid = std::min(elements, raw.size() / element_size);
    for (std::size_t b = 0; elements > 0 && b < element_size; ++b) {
        const std::size_t plane = b * elements;
        const bool store = valid > 0 && sampled_entropy_bits({shuffled.data() + plane, valid}) >= k_store_entropy_bits;
        if (valid > 0) segments.push_back({plane, valid, store ? 0 : level});
        if (elements > valid) segments.push_back({plane + valid, elements - valid, level, Z_RLE});
        ++(store ? encoding.planes_stored : encoding.planes_compressed);
    }
    const std::size_t leftover = chunk_size - elements * element_size;  // rides with the last segment
    if (segments.empty()) {
        segments.push_back({0, leftover, level, Z_DEFAULT_STRATEGY});
    } else {
        segments.back().size += leftover;
    }

    out.resize(std::max<std::size_t>(out.capacity(), chunk_size + chunk_size / 64 + 1024));
    Deflater deflater(level);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& segment = segments[i];
        deflater.feed(shuffled.data() + segment.begin, segment.size, segment.level, segment.strategy,
                      i + 1 == segments.size(), out);
    }
    out.resize(deflater.written());
    return encoding;
}

std::vector<std::byte> decode_shuffle_deflate(std::span<const unsigned char> encoded, std::size_t element_size,
                                              std::size_t raw_size) {
    std::vector<unsigned char> shuffled(raw_size);
    uLongf size = static_cast<uLongf>(raw_size);
    if (uncompress(shuffled.data(), &size, encoded.data(), static_cast<uLong>(encoded.size())) != Z_OK ||
        size != raw_size) {
        throw std::runtime_error("decode_shuffle_deflate: the stream does not inflate to " + std::to_string(raw_size) +
                                 " bytes");
    }
    std::vector<std::byte> raw(raw_size);
    const std::size_t elements = raw_size / element_size;
    for (std::size_t b = 0; b < element_size; ++b) {
        for (std::size_t i = 0; i < elements; ++i) {
            raw[i * element_size + b] = static_cast<std::byte>(shuffled[b * elements + i]);
        }
    }
    for (std::size_t i = elements * element_size; i < raw_size; ++i) raw[i] = static_cast<std::byte>(shuffled[i]);
    return raw;
}

}  // namespace collidescope::recorder
