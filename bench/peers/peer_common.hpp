#pragma once
// What the peer benchmarks share (bench/peers): pair lists, timing, topology revisions and
// the comparison of a peer's pairs with the exact ones.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace collidescope::peers {

using Clock = std::chrono::steady_clock;
using PairSet = std::vector<TrianglePair>;

inline double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The objects' topology revisions: a peer rebuilds from scratch when they change (fractures).
inline std::vector<std::uint64_t> revisions(const Frame& frame) {
    std::vector<std::uint64_t> out;
    for (const ObjectFrame& object : frame.objects) out.push_back(object.topology->revision);
    return out;
}

/// Sorts and removes duplicates.
inline void sort_unique(PairSet& pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

/// Pairs in `got` not in `exact` (extra) and in `exact` not in `got` (missed); `exact` sorted
/// and unique.
inline std::pair<std::size_t, std::size_t> difference(PairSet got, const PairSet& exact) {
    sort_unique(got);
    PairSet extra;
    PairSet missed;
    std::set_difference(got.begin(), got.end(), exact.begin(), exact.end(), std::back_inserter(extra));
    std::set_difference(exact.begin(), exact.end(), got.begin(), got.end(), std::back_inserter(missed));
    return {extra.size(), missed.size()};
}

}  // namespace collidescope::peers
