// keep_freed_memory (collidescope/memory.hpp): glibc's mallopt.

#include "collidescope/memory.hpp"

#include "collidescope/large_blocks.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc
#include <limits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace collidescope {

bool keep_freed_memory() {
    // The engine's own large arrays (collidescope/large_blocks.hpp): every freed block is kept.
    detail::set_large_block_cache_limit(std::numeric_limits<std::size_t>::max());
#if defined(__GLIBC__)
    // The largest fixed mmap threshold glibc accepts on 64-bit (DEFAULT_MMAP_THRESHOLD_MAX).
    constexpr int k_mmap_threshold = 32 * 1024 * 1024;
    const bool mmap_set = mallopt(M_MMAP_THRESHOLD, k_mmap_threshold) == 1;
    const bool trim_set = mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max()) == 1;
    return mmap_set && trim_set;
#else
    return false;
#endif
}

}  // namespace collidescope
