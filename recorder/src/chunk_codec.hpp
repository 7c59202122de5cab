#pragma once
// A chunk encoded as HDF5's shuffle filter followed by its deflate filter would encode it, but
// faster: written with H5Dwrite_chunk, any HDF5 reader (h5py, h5dump, the tool) decodes it
// with the filters the dataset declares. Why: float32 vertex positions are most of a
// recording, and after shuffling only their top byte plane (sign and exponent) compresses;
// the three mantissa planes are near-random (level 1 leaves them at 99.6-100.1% of their
// size on data sets A, C and E2), yet zlib spends most of its time searching them for
// matches. Here each byte plane whose sampled entropy says it will not compress goes out as
// deflate's stored blocks (a copy), the others at the requested level; the stream stays one
// valid zlib stream (deflateParams switches between them). docs/reference/recording.md has the figures.

#include <cstddef>
#include <span>
#include <vector>

namespace collidescope::recorder {

/// Byte planes whose sampled entropy is at least this many bits per byte are stored, not
/// compressed (8 = uniformly random bytes; Huffman coding alone saves about (8 - H) / 8).
inline constexpr double k_store_entropy_bits = 7.5;

/// How one chunk was encoded (for tests and figures).
struct ChunkEncoding {
    std::size_t planes_stored = 0;      ///< byte planes written as stored blocks
    std::size_t planes_compressed = 0;  ///< byte planes deflated at the level asked
};

/// Encodes `raw` followed by zeros up to `chunk_size` bytes (at least raw.size(); 0 = just
/// raw) into `out` (replaced): the shuffle filter's byte transposition (whole elements of
/// `element_size` bytes, leftover bytes at the end), then one zlib stream in which each
/// plane's part from `raw` is deflated at `level` (1-9) or stored, as its entropy says, and
/// each plane's zero padding is deflated. Decodes with H5Z shuffle + deflate (inflate, then
/// un-shuffle) to exactly `chunk_size` bytes. The padding lets a chunk that a frame only
/// partly fills be written whole (a chunk's stored form always decodes to the full chunk).
ChunkEncoding encode_shuffle_deflate(std::span<const std::byte> raw, std::size_t element_size, int level,
                                     std::vector<unsigned char>& out, std::size_t chunk_size = 0);

/// The slow, obvious inverse, for tests: inflate, then un-shuffle. Throws std::runtime_error on
/// a stream that does not inflate to `raw_size` bytes.
std::vector<std::byte> decode_shuffle_deflate(std::span<const unsigned char> encoded, std::size_t element_size,
                                              std::size_t raw_size);

/// Shannon entropy, bits per byte, of a sample of `bytes` (16 runs of 256 bytes spread over it,
/// or all of it when shorter than 4096).
double sampled_entropy_bits(std::span<const unsigned char> bytes);

}  // namespace collidescope::recorder
