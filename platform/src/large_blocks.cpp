// Large blocks (collidescope/large_blocks.hpp): mappings in transparent huge pages, cut into slots
// below 2 MiB, and a cache of freed blocks for the next allocation of about the same size.

#include "collidescope/large_blocks.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <iterator>
#include <map>
#include <mutex>
#include <unordered_map>
#include <vector>

#include <sys/mman.h>

namespace collidescope::detail {
namespace {

constexpr std::size_t k_huge_page = std::size_t{2} << 20;

std::size_t round_up(std::size_t bytes) { return (bytes + k_huge_page - 1) / k_huge_page * k_huge_page; }

/// `size` bytes (a multiple of 2 MiB) mapped at a 2 MiB boundary and advised as huge pages.
void* map_block(std::size_t size) {
    const std::size_t reserved = size + k_huge_page;
    void* mapped = mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + k_huge_page - 1) & ~(k_huge_page - 1);
    // Unmap the slack before and after the aligned block.
    if (aligned > start) munmap(mapped, aligned - start);
    const std::size_t tail = start + reserved - (aligned + size);
    if (tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
    void* block = reinterpret_cast<void*>(aligned);
    // Advice only: where transparent huge pages are off the block faults in 4 KiB pages.
    madvise(block, size, MADV_HUGEPAGE);
    return block;
}

/// The size class of a block below 2 MiB: a power of two from k_large_block on.
std::size_t slot_size(std::size_t bytes) { return std::bit_ceil(std::max(bytes, k_large_block)); }

class BlockCache {
public:
    void* allocate(std::size_t bytes) {
        const std::size_t size = bytes < k_huge_page ? slot_size(bytes) : round_up(bytes);
        if (size < k_huge_page) return allocate_slot(size);
        {
            std::lock_guard lock(m_mutex);
            // The smallest cached block that fits, if it wastes at most its request again.
            const auto found = m_cached.lower_bound(size);
            if (found != m_cached.end() && found->first <= 2 * size) {
                void* block = found->second;
                m_in_use.emplace(block, found->first);
                m_cached_bytes -= found->first;
                m_cached.erase(found);
                return block;
            }
        }
        void* block = map_block(size);
        std::lock_guard lock(m_mutex);
        m_in_use.emplace(block, size);
        m_mapped_bytes += size;
        return block;
    }

    void free(void* block, BlockReuse reuse) noexcept {
        std::lock_guard lock(m_mutex);
        const auto found = m_in_use.find(block);
        if (found == m_in_use.end()) return;  // not one of ours
        const std::size_t size = found->second;
        m_in_use.erase(found);
        if (size < k_huge_page) {
            m_slots[std::countr_zero(size)].push_back(block);
            return;
        }
        if (reuse == BlockReuse::Keep && m_cached_bytes + size <= m_limit) {
            m_cached.emplace(size, block);
            m_cached_bytes += size;
            return;
        }
        unmap(block, size);
    }

    void set_limit(std::size_t bytes) {
        std::lock_guard lock(m_mutex);
        m_limit = bytes;
        // Largest first, until what stays fits.
        while (m_cached_bytes > m_limit) {
            const auto largest = std::prev(m_cached.end());
            m_cached_bytes -= largest->first;
            unmap(largest->second, largest->first);
            m_cached.erase(largest);
        }
    }

    LargeBlockStats stats() {
        std::lock_guard lock(m_mutex);
        std::size_t free_slots = 0;
        for (const std::vector<void*>& slots : m_slots) free_slots += slots.size();
        return {m_mapped_bytes, m_cached_bytes, m_cached.size(), free_slots};
    }

private:
    /// A slot of `size` (a power of two under 2 MiB): a free one, or the first of a new 2 MiB
    /// mapping cut into slots of that size.
    void* allocate_slot(std::size_t size) {
        std::vector<void*>& free_slots = m_slots[std::countr_zero(size)];
        {
            std::lock_guard lock(m_mutex);
            if (!free_slots.empty()) {
                void* slot = free_slots.back();
                free_slots.pop_back();
                m_in_use.emplace(slot, size);
                return slot;
            }
        }
        char* chunk = static_cast<char*>(map_block(k_huge_page));
        std::lock_guard lock(m_mutex);
        m_mapped_bytes += k_huge_page;
        for (std::size_t at = k_huge_page - size; at > 0; at -= size) free_slots.push_back(chunk + at);
        m_in_use.emplace(chunk, size);
        return chunk;
    }

    void unmap(void* block, std::size_t size) noexcept {
        munmap(block, size);
        m_mapped_bytes -= size;
    }

    std::mutex m_mutex;
    std::multimap<std::size_t, void*> m_cached;      ///< free blocks of 2 MiB and more, by size
    std::array<std::vector<void*>, 21> m_slots;      ///< free slots by log2 of their size
    std::unordered_map<void*, std::size_t> m_in_use;  ///< handed-out blocks' sizes (slot or mapping)
    std::size_t m_cached_bytes = 0;
    std::size_t m_mapped_bytes = 0;
    std::size_t m_limit = std::size_t{256} << 20;
};

/// Never destroyed: vectors in static storage may free their blocks after main returns.
BlockCache& cache() {
    static BlockCache* const instance = new BlockCache;
    return *instance;
}

}  // namespace

void* allocate_large_block(std::size_t bytes) { return cache().allocate(bytes); }

void free_large_block(void* block, std::size_t /*bytes*/, BlockReuse reuse) noexcept { cache().free(block, reuse); }

void set_large_block_cache_limit(std::size_t bytes) { cache().set_limit(bytes); }

LargeBlockStats large_block_stats() { return cache().stats(); }

}  // namespace collidescope::detail
