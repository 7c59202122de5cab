// LSD radix sort of Morton keys: per pass a histogram of one 11-bit digit, its prefix sums,
// and a stable scatter into the other buffer. One read of the keys counts every pass's digits,
// which says which passes can be skipped. Large inputs go in blocks on TBB's threads: per
// pass each block counts its digits, the offsets run digit by digit and block by block, and
// each block scatters its keys in order, so the result is the sequential one (and stable).
// Replaced tbb::parallel_sort (a comparison sort), which was 38% of an LBVH build of the
// 48k-triangle dragon (docs/explanation/algorithms.md, "Builds").

#include "bvh/radix_sort.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <span>
#include <utility>

namespace collidescope::bvh::detail {
namespace {

constexpr int k_digit_bits = 11;
constexpr std::size_t k_bins = std::size_t{1} << k_digit_bits;
constexpr int k_passes = (64 + k_digit_bits - 1) / k_digit_bits;
// Keys per block when sorting in parallel; below two blocks' worth, one thread sorts.
constexpr std::size_t k_block = std::size_t{1} << 16;

using Counts = std::array<std::uint32_t, k_bins>;

std::uint32_t digit(std::uint64_t code, int pass) {
    return static_cast<std::uint32_t>(code >> (pass * k_digit_bits)) & (k_bins - 1);
}

// One pass over `from` into `to`, on one thread, with the pass's digit counts already known.
void scatter_pass(std::span<const MortonKey> from, std::span<MortonKey> to, int pass, Counts offsets) {
    std::uint32_t sum = 0;
    for (std::uint32_t& c : offsets) sum += std::exchange(c, sum);
    for (const MortonKey& key : from) to[offsets[digit(key.code, pass)]++] = key;
}

// One pass over `from` into `to`, in `blocks` blocks on TBB's threads.
void scatter_pass(std::span<const MortonKey> from, std::span<MortonKey> to, int pass, std::size_t blocks) {
    const std::size_t n = from.size();
    const auto block_range = [&](std::size_t b) {
        return std::pair{from.begin() + static_cast<std::ptrdiff_t>(b * n / blocks),
                         from.begin() + static_cast<std::ptrdiff_t>((b + 1) * n / blocks)};
    };
    std::vector<Counts> offsets(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        offsets[b].fill(0);
        const auto [begin, end] = block_range(b);
        for (auto it = begin; it != end; ++it) ++offsets[b][digit(it->code, pass)];
    });
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < k_bins; ++d) {
        for (Counts& block : offsets) sum += std::exchange(block[d], sum);
    }
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        Counts& next = offsets[b];
        const auto [begin, end] = block_range(b);
        for (auto it = begin; it != end; ++it) to[next[digit(it->code, pass)]++] = *it;
    });
}

}  // namespace

void radix_sort(LargeVector<MortonKey>& keys, LargeVector<MortonKey>& scratch) {
    const std::size_t n = keys.size();
    if (n < 2) return;
    std::vector<Counts> counts(k_passes);
    for (Counts& c : counts) c.fill(0);
    for (const MortonKey& key : keys) {
        for (int pass = 0; pass < k_passes; ++pass) ++counts[pass][digit(key.code, pass)];
    }
    const auto threads = static_cast<std::size_t>(std::max(tbb::this_task_arena::max_concurrency(), 1));
    const std::size_t blocks = n < 2 * k_block || threads == 1 ? 1 : std::min(n / k_block, 4 * threads);
    scratch.resize(n);
    LargeVector<MortonKey>* from = &keys;
    LargeVector<MortonKey>* to = &scratch;
    for (int pass = 0; pass < k_passes; ++pass) {
        if (counts[pass][digit(keys[0].code, pass)] == n) continue;  // one digit value: order unchanged
        if (blocks == 1) {
            scatter_pass(*from, *to, pass, counts[pass]);
        } else {
            scatter_pass(*from, *to, pass, blocks);
        }
        std::swap(from, to);
    }
    if (from != &keys) keys.swap(*from);
}

}  // namespace collidescope::bvh::detail
