// keep_freed_memory (collidescope/memory.hpp): glibc takes both settings, and a process that
// took them still allocates, frees and reuses large blocks.

#include "collidescope/memory.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace collidescope {
namespace {

TEST(Memory, KeepFreedMemoryTakesItsSettings) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    (void)keep_freed_memory();  // the sanitizers' allocators replace glibc's and ignore mallopt
#else
    EXPECT_TRUE(keep_freed_memory());
#endif
    for (int round = 0; round < 3; ++round) {
        std::vector<double> block(std::size_t{4} << 20, round);  // 32 MiB: at the threshold
        std::vector<double> smaller(std::size_t{1} << 20, round);
        EXPECT_EQ(block.back() + smaller.back(), 2.0 * round);
    }
}

}  // namespace
}  // namespace collidescope
