#pragma once
// Large arrays in transparent huge pages, kept for reuse (the platform library's one block
// allocator, for the engine and the recorder; docs/explanation/architecture.md, "Memory between
// frames").
//
// A tree, its build's working memory and its wide layout are arrays of megabytes that a
// rebuild allocates again. Touching a fresh 4 KiB page cost 13.7 us on the project's 2-core VM
// (a bare-metal fault is some 0.25 us), so a cold build spent most of its time in page faults:
// a 1M-triangle LBVH build took 566 ms cold against about 100 ms in huge pages. Blocks of at
// least k_large_block bytes therefore come from mappings advised MADV_HUGEPAGE, 2 MiB aligned
// (one fault per 2 MiB where the kernel's transparent huge pages are "always" or "madvise";
// 4 KiB pages as before where they are "never"):
// - from 2 MiB on, a mapping of its own, rounded up to a multiple of 2 MiB; freed, it waits in
//   a cache for the next allocation of about its size (up to twice as large) instead of going
//   back to the kernel, while the cache holds less than its limit;
// - below, a slot of 256, 512 or 1024 KiB (the size rounded up to a power of two) carved from a
//   2 MiB mapping; freed slots wait for the next block of their size and are never unmapped.
// Either way a block wastes less than its size. Smaller arrays use operator new, and so does
// every array under AddressSanitizer, whose checks then keep covering them.
//
// The recorder's frame buffers (positions, pairs, survivors) take BlockReuse::Release: the
// engine's thread allocates them, the writer thread frees them, and a freed mapping goes back
// to the kernel at once instead of waiting in the cache. Through malloc, glibc's dynamic mmap
// threshold kept such blocks in its arenas (E4:large, 60 frames: peak RSS 1,138 MiB against
// 919 MiB with them mapped); doing that for the whole process (mallopt) made the engine's own
// per-frame buffers fault in fresh pages every frame (docs/reference/robustness.md, "Bounded
// memory").

#include <cstddef>
#include <new>
#include <vector>

namespace collidescope::detail {

/// Arrays of at least this many bytes are large blocks.
inline constexpr std::size_t k_large_block = std::size_t{256} << 10;

/// A block of at least `bytes` (>= k_large_block) bytes, aligned to its size class (at least
/// 256 KiB); throws std::bad_alloc.
/// Its contents are unspecified (a reused block keeps what it held).
void* allocate_large_block(std::size_t bytes);

/// What a freed block of 2 MiB or more does (slots below 2 MiB are always kept for reuse).
enum class BlockReuse {
    Keep,     ///< waits in the cache for the next block of about its size (the engine's arrays)
    Release,  ///< is unmapped at once (the recorder's frame buffers, freed by another thread)
};

/// Gives back a block of allocate_large_block: with Keep, kept for reuse (a mapping of its own
/// while the cache holds less than its limit; unmapped past it); with Release, a mapping of
/// its own is unmapped.
void free_large_block(void* block, std::size_t bytes, BlockReuse reuse = BlockReuse::Keep) noexcept;

/// The cache's limit in bytes: 256 MiB unless set. keep_freed_memory() lifts it (the process
/// keeps its peak footprint, as it asks of malloc). Blocks over a new, lower limit are unmapped.
void set_large_block_cache_limit(std::size_t bytes);

/// What the cache holds now (tests and the docs' measurements).
struct LargeBlockStats {
    std::size_t mapped_bytes = 0;  ///< mappings: blocks in use or waiting, and the slots' 2 MiB
    std::size_t cached_bytes = 0;  ///< blocks of 2 MiB and more waiting for reuse
    std::size_t cached_blocks = 0;
    std::size_t free_slots = 0;    ///< slots below 2 MiB waiting for reuse
};
LargeBlockStats large_block_stats();

/// std::allocator's contract; arrays of k_large_block bytes and more are large blocks, freed
/// as `reuse` says.
template <class T, BlockReuse reuse = BlockReuse::Keep>
struct LargeBlockAllocator {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = LargeBlockAllocator<U, reuse>;
    };

    LargeBlockAllocator() = default;
    template <class U>
    LargeBlockAllocator(const LargeBlockAllocator<U, reuse>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
#if !defined(__SANITIZE_ADDRESS__)
        if (bytes >= k_large_block) return static_cast<T*>(allocate_large_block(bytes));
#endif
        return static_cast<T*>(::operator new(bytes, std::align_val_t{alignof(T)}));
    }
    void deallocate(T* p, [[maybe_unused]] std::size_t n) noexcept {
#if !defined(__SANITIZE_ADDRESS__)
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= k_large_block) return free_large_block(p, bytes, reuse);
#endif
        ::operator delete(p, std::align_val_t{alignof(T)});
    }

    template <class U>
    friend bool operator==(const LargeBlockAllocator&, const LargeBlockAllocator<U, reuse>&) noexcept {
        return true;
    }
};

/// A std::vector whose storage is a large block once it reaches k_large_block bytes.
template <class T, BlockReuse reuse = BlockReuse::Keep>
using LargeVector = std::vector<T, LargeBlockAllocator<T, reuse>>;

}  // namespace collidescope::detail
