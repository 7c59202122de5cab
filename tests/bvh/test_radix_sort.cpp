// The LBVH's radix sort against std::sort on the same keys: seeded random codes with many
// duplicates, codes that differ only in high or only in low bits (passes skipped), and the
// sizes at the edges (0, 1, 2).

#include "bvh/radix_sort.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <random>

namespace collidescope::bvh::detail {
namespace {

// Keys in id order (as the builder makes them), codes drawn by `code`.
template <typename Draw>
std::vector<MortonKey> keys_of(std::size_t n, Draw code) {
    std::vector<MortonKey> keys(n);
    for (std::size_t i = 0; i < n; ++i) keys[i] = {code(), static_cast<std::uint32_t>(i)};
    return keys;
}

void expect_sorts_like_std_sort(std::vector<MortonKey> keys, const std::string& what) {
    std::vector<MortonKey> expected = keys;
    std::sort(expected.begin(), expected.end());  // by (code, id): what stability must give
    // The builder's storage: past 1 MiB (65,536 keys), large blocks (collidescope/large_blocks.hpp).
    LargeVector<MortonKey> sorted(keys.begin(), keys.end()), scratch;
    radix_sort(sorted, scratch);
    EXPECT_TRUE(std::ranges::equal(sorted, expected)) << what;
}

TEST(RadixSort, SortsLikeStdSortWithTheIndexAsTieBreak) {
    const std::uint64_t seed = 0x5eed'4ad1;
    std::printf("seed %#llx\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    for (const std::size_t n : {0u, 1u, 2u, 3u, 100u, 4097u, 70000u}) {
        const std::string size = "n = " + std::to_string(n);
        expect_sorts_like_std_sort(keys_of(n, [&] { return rng() >> 1; }), size + ", 63-bit codes");
        expect_sorts_like_std_sort(keys_of(n, [&] { return rng() % 7; }), size + ", 7 distinct codes");
        expect_sorts_like_std_sort(keys_of(n, [&] { return (rng() % 5) << 58; }), size + ", top bits only");
        expect_sorts_like_std_sort(keys_of(n, [&] { return (rng() % 3) << 22 | (rng() % 3); }),
                                   size + ", two digits vary");
        expect_sorts_like_std_sort(keys_of(n, [] { return std::uint64_t{42}; }), size + ", one code");
        expect_sorts_like_std_sort(keys_of(n, [&] { return ~std::uint64_t{0} - rng() % 2; }), size + ", all bits set");
    }
}

// Large inputs sort in blocks on TBB's threads: the same result for every thread count.
TEST(RadixSort, SortsInBlocksOnAnyThreadCountLikeStdSort) {
    const std::uint64_t seed = 0x5eed'b10c;
    std::printf("seed %#llx\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    const std::vector<MortonKey> many_codes = keys_of(300000, [&] { return rng() >> 1; });
    const std::vector<MortonKey> few_codes = keys_of(300000, [&] { return (rng() % 1000) << 30; });
    for (const int threads : {1, 2, 4}) {
        tbb::task_arena arena(threads);
        arena.execute([&] {
            expect_sorts_like_std_sort(many_codes, std::to_string(threads) + " threads, 63-bit codes");
            expect_sorts_like_std_sort(few_codes, std::to_string(threads) + " threads, 1000 codes");
        });
    }
}

TEST(RadixSort, KeysArrivingOutOfIdOrderKeepTheirArrivalOrderAmongEqualCodes) {
    LargeVector<MortonKey> keys{{5, 9}, {1, 4}, {5, 2}, {1, 7}, {0, 3}};
    LargeVector<MortonKey> scratch;
    radix_sort(keys, scratch);
    const std::vector<MortonKey> stable{{0, 3}, {1, 4}, {1, 7}, {5, 9}, {5, 2}};
    EXPECT_TRUE(std::ranges::equal(keys, stable));
}

}  // namespace
}  // namespace collidescope::bvh::detail
