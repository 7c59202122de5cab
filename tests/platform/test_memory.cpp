// keep_freed_memory (collidescope/memory.hpp): glibc takes both settings, the engine's large
// blocks are kept past their default limit, and a process that took them still allocates,
// frees and reuses large blocks.

#include "collidescope/memory.hpp"

#include "collidescope/large_blocks.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace collidescope {
namespace {

TEST(Memory, KeepFreedMemoryTakesItsSettings) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    // The sanitizers' allocators replace glibc's and ignore mallopt; the large blocks below
    // are the engine's own and still checked.
    (void)keep_freed_memory();
#else
    EXPECT_TRUE(keep_freed_memory());
#endif
    for (int round = 0; round < 3; ++round) {
        std::vector<double> block(std::size_t{4} << 20, round);  // 32 MiB: at the threshold
        std::vector<double> smaller(std::size_t{1} << 20, round);
        EXPECT_EQ(block.back() + smaller.back(), 2.0 * round);
    }
}

// Past keep_freed_memory(), freed large blocks are all kept: 320 MiB of 8 MiB blocks, more than
// the 256 MiB the cache keeps by default (collidescope/large_blocks.hpp). Untouched, so the pages
// are never faulted in.
TEST(Memory, KeepFreedMemoryKeepsEveryFreedLargeBlock) {
    (void)keep_freed_memory();
    constexpr std::size_t k_block = std::size_t{8} << 20;
    const std::size_t before = detail::large_block_stats().cached_bytes;
    std::vector<void*> blocks;
    for (int i = 0; i < 40; ++i) blocks.push_back(detail::allocate_large_block(k_block));
    for (void* block : blocks) detail::free_large_block(block, k_block);
    EXPECT_GE(detail::large_block_stats().cached_bytes, before + 40 * k_block);
}

}  // namespace
}  // namespace collidescope
