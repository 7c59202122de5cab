#pragma once
// TrianglePair's order, fast (engine/src/stages, private): (obj_a, tri_a) then (obj_b,
// tri_b), each packed into one 64-bit word (the same order as the member-wise comparison),
// and a sort in that order, on TBB's threads when there are many elements: the per-frame
// pipeline's pairs and the between-frames contacts, whose pairs are distinct, so the order is
// one whatever the threads.

#include "collidescope/types.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace collidescope {

inline bool packed_pair_less(const TrianglePair& x, const TrianglePair& y) {
    const std::uint64_t xa = std::uint64_t{x.obj_a} << 32 | x.tri_a, ya = std::uint64_t{y.obj_a} << 32 | y.tri_a;
    if (xa != ya) return xa < ya;
    return (std::uint64_t{x.obj_b} << 32 | x.tri_b) < (std::uint64_t{y.obj_b} << 32 | y.tri_b);
}

/// Sorts `items` by `pair_of(item)` in TrianglePair's order.
template <class T, class PairOf>
void sort_by_pair(std::vector<T>& items, PairOf pair_of) {
    const auto less = [&](const T& x, const T& y) { return packed_pair_less(pair_of(x), pair_of(y)); };
    if (items.size() >= (std::size_t{1} << 15)) {
        tbb::parallel_sort(items.begin(), items.end(), less);
    } else {
        std::sort(items.begin(), items.end(), less);
    }
}

}  // namespace collidescope
