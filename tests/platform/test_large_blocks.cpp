// Large blocks (platform/include/collidescope/large_blocks.hpp): every size class aligned,
// writable and disjoint from every other live block, freed blocks reused, the cache's limit
// kept, a released block unmapped, and a LargeVector equal to a std::vector through its growth.

#include "collidescope/large_blocks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <thread>
#include <vector>

namespace collidescope::detail {
namespace {

constexpr std::size_t k_kib = 1024;
constexpr std::size_t k_mib = 1024 * k_kib;

struct Live {
    std::uint8_t* block;
    std::size_t bytes;
    std::uint8_t tag;
};

// Writes `tag` over the whole block: first, middle and last byte of every 4 KiB page.
void fill(const Live& live) {
    for (std::size_t at = 0; at < live.bytes; at += 4096) live.block[at] = live.tag;
    live.block[live.bytes / 2] = live.tag;
    live.block[live.bytes - 1] = live.tag;
}

bool intact(const Live& live) {
    for (std::size_t at = 0; at < live.bytes; at += 4096) {
        if (live.block[at] != live.tag) return false;
    }
    return live.block[live.bytes / 2] == live.tag && live.block[live.bytes - 1] == live.tag;
}

TEST(LargeBlocks, EverySizeClassIsAlignedWritableAndDisjoint) {
    const std::vector<std::size_t> sizes = {k_large_block,     k_large_block + 1, 300 * k_kib, 512 * k_kib,
                                            k_mib - 1,         k_mib,             1536 * k_kib, 2 * k_mib - 1,
                                            2 * k_mib,         3 * k_mib,         5 * k_mib + 7};
    std::vector<Live> live;
    for (int round = 0; round < 3; ++round) {
        for (const std::size_t bytes : sizes) {
            auto* block = static_cast<std::uint8_t*>(allocate_large_block(bytes));
            const std::size_t align = std::min(std::bit_ceil(bytes), 2 * k_mib);
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % std::min(align, 2 * k_mib), 0u) << bytes;
            live.push_back({block, bytes, static_cast<std::uint8_t>(live.size() + 1)});
            fill(live.back());
        }
    }
    for (const Live& a : live) {
        EXPECT_TRUE(intact(a)) << a.bytes;
        for (const Live& b : live) {
            if (&a == &b) continue;
            EXPECT_TRUE(a.block + a.bytes <= b.block || b.block + b.bytes <= a.block)
                << a.bytes << " and " << b.bytes << " overlap";
        }
    }
    for (const Live& a : live) free_large_block(a.block, a.bytes);
}

TEST(LargeBlocks, FreedBlocksAreReusedAndTheLimitUnmapsThePast) {
    set_large_block_cache_limit(0);  // no cached block from an earlier test
    set_large_block_cache_limit(std::size_t{256} << 20);
    for (const std::size_t bytes : {300 * k_kib, k_mib, 6 * k_mib}) {
        void* first = allocate_large_block(bytes);
        free_large_block(first, bytes);
        void* again = allocate_large_block(bytes);
        EXPECT_EQ(again, first) << bytes;
        free_large_block(again, bytes);
    }
    // A cached 6 MiB block serves a 5 MiB request (at most twice the size), not a 2 MiB one.
    void* six = allocate_large_block(6 * k_mib);
    free_large_block(six, 6 * k_mib);
    void* five = allocate_large_block(5 * k_mib);
    EXPECT_EQ(five, six);
    free_large_block(five, 5 * k_mib);
    void* two = allocate_large_block(2 * k_mib);
    EXPECT_NE(two, six);
    free_large_block(two, 2 * k_mib);

    const LargeBlockStats cached = large_block_stats();
    EXPECT_GE(cached.cached_bytes, 8 * k_mib);
    set_large_block_cache_limit(0);  // every cached block of 2 MiB and more is unmapped
    const LargeBlockStats none = large_block_stats();
    EXPECT_EQ(none.cached_bytes, 0u);
    EXPECT_EQ(none.cached_blocks, 0u);
    EXPECT_LE(none.mapped_bytes + cached.cached_bytes, cached.mapped_bytes);
    void* unmapped = allocate_large_block(4 * k_mib);
    free_large_block(unmapped, 4 * k_mib);  // over the limit: unmapped at once
    EXPECT_EQ(large_block_stats().mapped_bytes, none.mapped_bytes);
    set_large_block_cache_limit(std::size_t{256} << 20);
}

// Random allocations and frees from several threads at once; every live block keeps its
// bytes (two blocks handed out over each other would overwrite one another's tags).
TEST(LargeBlocks, ThreadsAllocatingAndFreeingAtRandomKeepEveryBlocksBytes) {
    const std::uint64_t seed = 0x1a76'eb10;
    std::printf("seed %#llx\n", static_cast<unsigned long long>(seed));
    std::vector<std::thread> threads;
    std::vector<int> failures(4, 0);
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            std::mt19937_64 rng(seed + static_cast<std::uint64_t>(t));
            std::vector<Live> live;
            for (int step = 0; step < 400; ++step) {
                if (!live.empty() && (live.size() > 12 || rng() % 3 == 0)) {
                    const std::size_t k = rng() % live.size();
                    failures[t] += intact(live[k]) ? 0 : 1;
                    free_large_block(live[k].block, live[k].bytes);
                    live.erase(live.begin() + static_cast<std::ptrdiff_t>(k));
                    continue;
                }
                const std::size_t bytes = k_large_block + rng() % (7 * k_mib);
                auto* block = static_cast<std::uint8_t*>(allocate_large_block(bytes));
                live.push_back({block, bytes, static_cast<std::uint8_t>(1 + rng() % 255)});
                fill(live.back());
            }
            for (const Live& l : live) {
                failures[t] += intact(l) ? 0 : 1;
                free_large_block(l.block, l.bytes);
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    for (int t = 0; t < 4; ++t) EXPECT_EQ(failures[t], 0) << "thread " << t;
}

TEST(LargeBlocks, LargeVectorHoldsWhatAStdVectorHoldsThroughItsGrowth) {
    LargeVector<std::uint64_t> large;
    std::vector<std::uint64_t> plain;
    for (std::uint64_t k = 0; k < 3 * k_mib / sizeof(std::uint64_t); ++k) {  // crosses every class
        large.push_back(k * 2654435761u);
        plain.push_back(k * 2654435761u);
    }
    EXPECT_TRUE(std::equal(large.begin(), large.end(), plain.begin(), plain.end()));
    LargeVector<std::uint64_t> copy = large;
    large.clear();
    large.shrink_to_fit();
    EXPECT_TRUE(std::equal(copy.begin(), copy.end(), plain.begin(), plain.end()));
}

// BlockReuse::Release (the recorder's frame buffers): a freed mapping of its own goes back to
// the kernel at once, and the cache holds no more than before.
TEST(LargeBlocks, ReleasedBlocksAreUnmappedNotCached) {
    const LargeBlockStats before = large_block_stats();
    constexpr std::size_t bytes = 6 * k_mib;
    auto* block = static_cast<std::uint8_t*>(allocate_large_block(bytes));
    std::memset(block, 7, bytes);
    const LargeBlockStats in_use = large_block_stats();
    free_large_block(block, bytes, BlockReuse::Release);
    const LargeBlockStats after = large_block_stats();
    EXPECT_EQ(after.cached_bytes, in_use.cached_bytes);
    EXPECT_EQ(after.cached_blocks, in_use.cached_blocks);
    EXPECT_LT(after.mapped_bytes, in_use.mapped_bytes);
    EXPECT_LE(after.mapped_bytes, before.mapped_bytes);

    // A vector of released blocks through its growth: every block back, none cached.
    {
        LargeVector<double, BlockReuse::Release> grown;
        for (int i = 0; i < 1 << 20; ++i) grown.push_back(i);
        EXPECT_EQ(grown[12345], 12345.0);
    }
    EXPECT_EQ(large_block_stats().cached_bytes, after.cached_bytes);
}

}  // namespace
}  // namespace collidescope::detail
