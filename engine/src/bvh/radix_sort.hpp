#pragma once
// Sorting the LBVH's Morton keys: a stable least-significant-digit radix sort (engine/src/bvh,
// private). The keys arrive in triangle order, so stability gives the triangle index as the
// tie-break between equal codes, as `(code, id)` order does.

#include "collidescope/large_blocks.hpp"

#include <cstdint>
#include <vector>

namespace collidescope::bvh::detail {

using collidescope::detail::LargeVector;

/// A triangle's Morton code and its index.
struct MortonKey {
    std::uint64_t code;
    std::uint32_t id;

    friend bool operator<(const MortonKey& a, const MortonKey& b) {
        return a.code != b.code ? a.code < b.code : a.id < b.id;
    }
    friend bool operator==(const MortonKey&, const MortonKey&) = default;
};

/// Sorts `keys` by code, stably: keys with equal codes keep their relative order. 11-bit digits
/// (six passes over 64 bits); a pass whose digit is the same for every key is skipped, so
/// codes that vary in few bits cost few passes. `scratch` is resized and overwritten.
void radix_sort(LargeVector<MortonKey>& keys, LargeVector<MortonKey>& scratch);

}  // namespace collidescope::bvh::detail
