// sort_by_pair against std::sort in TrianglePair's member-wise order: distinct random pairs,
// with indices narrow enough for the radix path and too wide for it (the comparison sort),
// below and above the sizes where each path starts; and with repeated pairs, as the pipeline
// sorts them before removing the repeats.

#include "stages/pair_order.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>

namespace collidescope {
namespace {

struct Tagged {
    TrianglePair pair;
    int tag;  ///< travels with its pair
};

void check_sorts(std::uint64_t seed, std::size_t count, std::uint32_t objects, std::uint32_t triangles) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint32_t> object(0, objects - 1), triangle(0, triangles - 1);
    std::set<TrianglePair> seen;
    std::vector<Tagged> items;
    while (items.size() < count) {
        const TrianglePair p = make_pair_ordered(object(rng), triangle(rng), object(rng), triangle(rng));
        if (seen.insert(p).second) items.push_back({p, static_cast<int>(items.size())});
    }
    std::vector<Tagged> expected = items;
    std::sort(expected.begin(), expected.end(), [](const Tagged& x, const Tagged& y) { return x.pair < y.pair; });
    sort_by_pair(items, [](const Tagged& t) -> const TrianglePair& { return t.pair; });
    std::printf("seed %#llx: %zu pairs, objects < %u, triangles < %u\n", static_cast<unsigned long long>(seed), count,
                objects, triangles);
    ASSERT_EQ(items.size(), expected.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        ASSERT_EQ(items[i].pair, expected[i].pair) << "seed " << seed << " at " << i;
        ASSERT_EQ(items[i].tag, expected[i].tag) << "seed " << seed << " at " << i;
    }
}

TEST(PairOrder, SortsAsTheMemberWiseOrderOnEitherPath) {
    // Radix: 3 + 20 bits a half; one object (0 bits); the widest that fits (32 bits a half).
    check_sorts(0x5041, 5000, 5, 1 << 20);
    check_sorts(0x5042, 70000, 1, 300000);
    check_sorts(0x5043, 20000, 1 << 8, 1u << 24);
    check_sorts(0x5047, 8000, 1, 0xFFFFFFFFu);  // 0 + 32 bits a half
    // Too wide for one word: the comparison sort, below and above its parallel size.
    check_sorts(0x5044, 20000, 1 << 8, 1u << 25);
    check_sorts(0x5045, 40000, 3, 0xFFFFFFFFu);
    // Below the radix path's size.
    check_sorts(0x5046, 100, 4, 50);
}

TEST(PairOrder, RepeatedPairsSortAsTheirValues) {
    const std::uint64_t seed = 0x5048;
    std::mt19937_64 rng(seed);
    for (const std::uint32_t triangles : {64u, 0xFFFFFFFFu}) {  // the radix path, then the comparison sort
        std::uniform_int_distribution<std::uint32_t> triangle(0, triangles - 1);
        std::vector<TrianglePair> pairs;
        for (int i = 0; i < 6000; ++i) pairs.push_back(make_pair_ordered(i % 3, triangle(rng), 2, triangle(rng)));
        for (int i = 0; i < 6000; i += 3) pairs.push_back(pairs[i]);  // a third of them twice
        std::vector<TrianglePair> expected = pairs;
        std::sort(expected.begin(), expected.end());
        sort_by_pair(pairs, [](const TrianglePair& p) -> const TrianglePair& { return p; });
        std::printf("seed %#llx: %zu pairs with repeats, triangles < %u\n", static_cast<unsigned long long>(seed),
                    pairs.size(), triangles);
        ASSERT_EQ(pairs, expected) << "seed " << seed;
    }
}

}  // namespace
}  // namespace collidescope
