#pragma once
// Storage for the recorder's frame-sized buffers (positions, pairs, survivors): blocks of
// 1 MiB and more are mapped with mmap and unmapped when freed, so they never sit in malloc's
// arenas. The engine's thread allocates them and the writer thread frees them; through malloc,
// glibc's dynamic mmap threshold (raised to a block's size after its first free) kept such
// blocks in the arenas: E4:large, 60 frames, peak RSS 1,138 MiB against 919 MiB with every
// block of 1 MiB or more mapped. Doing that for the whole process (mallopt) made the engine's
// own per-frame traversal buffers fault in fresh pages every frame: C, `record --method
// aabb`, 0.8-1.0 s of system time against 0.2 s (docs/reference/robustness.md, "Bounded memory").

#include <cstddef>
#include <new>
#include <vector>

#include <sys/mman.h>

namespace collidescope::recorder {

template <class T>
struct LargeBlockAllocator {
    using value_type = T;
    static constexpr std::size_t k_mapped_bytes = std::size_t{1} << 20;  ///< from this size on: mmap

    LargeBlockAllocator() = default;
    template <class U>
    LargeBlockAllocator(const LargeBlockAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < k_mapped_bytes) return static_cast<T*>(::operator new(bytes));
        void* block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (block == MAP_FAILED) throw std::bad_alloc();
        return static_cast<T*>(block);
    }
    void deallocate(T* block, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < k_mapped_bytes) {
            ::operator delete(block);
        } else {
            munmap(block, bytes);
        }
    }
    template <class U>
    bool operator==(const LargeBlockAllocator<U>&) const noexcept {
        return true;
    }
};

/// A vector whose large buffers are mapped (see above).
template <class T>
using LargeVector = std::vector<T, LargeBlockAllocator<T>>;

}  // namespace collidescope::recorder
