#pragma once
// TrianglePair's order, fast (engine/src/stages, private): (obj_a, tri_a) then (obj_b,
// tri_b), and a sort in that order for the per-frame pipeline's pairs and the between-frames
// contacts. Where the four indices fit one 64-bit word at the widths the largest of them
// needs, the sort is bvh's radix sort of those words (each with its element's index, on TBB's
// threads when there are many), and the elements are then gathered in that order; else a
// comparison sort. The between-frames contacts' pairs are distinct, and the pipeline's
// duplicates (unique removes them after) are equal values, so the result is one whatever the
// threads or the path.

#include "bvh/radix_sort.hpp"
#include "collidescope/types.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

namespace collidescope {

/// The member-wise order, each of (obj_a, tri_a) and (obj_b, tri_b) packed into one 64-bit word.
inline bool packed_pair_less(const TrianglePair& x, const TrianglePair& y) {
    const std::uint64_t xa = std::uint64_t{x.obj_a} << 32 | x.tri_a, ya = std::uint64_t{y.obj_a} << 32 | y.tri_a;
    if (xa != ya) return xa < ya;
    return (std::uint64_t{x.obj_b} << 32 | x.tri_b) < (std::uint64_t{y.obj_b} << 32 | y.tri_b);
}

/// Sorts `items` by `pair_of(item)` in TrianglePair's order. On half a million contacts an
/// interval (coplanar-stack), the comparison sort was 9% of the samples at one thread.
template <class T, class PairOf>
void sort_by_pair(std::vector<T>& items, PairOf pair_of) {
    constexpr std::size_t k_radix_from = 4096;  // below this, a comparison sort (no gather)
    const std::size_t n = items.size();
    if (n >= k_radix_from && n <= std::numeric_limits<std::uint32_t>::max()) {
        std::uint32_t objects = 0, triangles = 0;
        for (const T& item : items) {
            const TrianglePair& p = pair_of(item);
            objects |= p.obj_a | p.obj_b;
            triangles |= p.tri_a | p.tri_b;
        }
        // The bits the largest index of each kind needs: (obj_a, tri_a, obj_b, tri_b) at those
        // widths, concatenated, order as the pairs do.
        const int object_bits = std::bit_width(objects), triangle_bits = std::bit_width(triangles);
        const int half = object_bits + triangle_bits;
        if (half <= 32) {
            bvh::detail::LargeVector<bvh::detail::MortonKey> keys, scratch;
            keys.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                const TrianglePair& p = pair_of(items[i]);
                const std::uint64_t a = std::uint64_t{p.obj_a} << triangle_bits | p.tri_a;
                const std::uint64_t b = std::uint64_t{p.obj_b} << triangle_bits | p.tri_b;
                keys[i] = {a << half | b, static_cast<std::uint32_t>(i)};
            }
            bvh::detail::radix_sort(keys, scratch);
            std::vector<T> sorted;
            sorted.reserve(n);
            for (const bvh::detail::MortonKey& key : keys) sorted.push_back(items[key.id]);
            items.swap(sorted);
            return;
        }
    }
    const auto less = [&](const T& x, const T& y) { return packed_pair_less(pair_of(x), pair_of(y)); };
    if (n >= (std::size_t{1} << 15)) {
        tbb::parallel_sort(items.begin(), items.end(), less);
    } else {
        std::sort(items.begin(), items.end(), less);
    }
}

}  // namespace collidescope
