#pragma once
// Equal keys grouped in linear time (engine/src/regions, private): items are numbered by the
// first item with an equal key, through an open-addressing table of their hashes. Sorting the
// keys to bring equal ones together cost n log n comparisons of random hashes, most of the
// curves' time on a frame of a thousand segments. The table is a large block once it is large
// (collidescope/large_blocks.hpp): a dense region's table is megabytes, touched for the first
// time in its first frame.

#include "collidescope/large_blocks.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace collidescope::regions {

class FirstSeen {
public:
    /// A table for up to `items` items.
    explicit FirstSeen(std::size_t items) : m_slots(std::bit_ceil(2 * items + 2)), m_mask(m_slots.size() - 1) {}

    /// The first item added whose key equals item's (`equal(j)`: item j's key equals item's),
    /// or `item` itself, which is then added. Equal keys must have equal hashes.
    template <typename Equal>
    std::uint32_t find_or_add(std::uint64_t hash, std::uint32_t item, Equal&& equal) {
        for (std::size_t s = (hash ^ hash >> 29) & m_mask;; s = (s + 1) & m_mask) {
            Slot& slot = m_slots[s];
            if (slot.item == k_empty) {
                slot = {hash, item};
                return item;
            }
            if (slot.hash == hash && equal(slot.item)) return slot.item;
        }
    }

private:
    static constexpr std::uint32_t k_empty = UINT32_MAX;
    struct Slot {
        std::uint64_t hash = 0;
        std::uint32_t item = k_empty;
    };
    detail::LargeVector<Slot> m_slots;
    std::size_t m_mask;
};

}  // namespace collidescope::regions
