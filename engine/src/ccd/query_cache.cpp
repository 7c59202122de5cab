// One thread's recent query results within an interval: a direct-mapped table.

#include "ccd/query_cache.hpp"

namespace collidescope::ccd {
namespace {

constexpr std::uint32_t k_vertex_face = 0, k_edge_edge = 1;

// A 64-bit mix (the finalizer of SplitMix64).
std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

}  // namespace

QueryKey QueryKey::vertex_face(std::uint32_t vertex_object, std::uint32_t v, std::uint32_t face_object, std::uint32_t tri,
                               int drop) {
    // The form in the first word: bit 0 vertex-face (0) or edge-edge (1), the planar axis + 1 above.
    return {{k_vertex_face | static_cast<std::uint32_t>(drop + 1) << 1, vertex_object, v, face_object, tri, 0, 0}};
}

QueryKey QueryKey::edge_edge(std::uint32_t p_object, std::uint32_t p0, std::uint32_t p1, std::uint32_t q_object,
                             std::uint32_t q0, std::uint32_t q1) {
    return {{k_edge_edge, p_object, p0, p1, q_object, q0, q1}};
}

std::uint64_t QueryCache::hash(const QueryKey& key) {
    // The words in pairs, each pair times its own odd constant (independent multiplies, not
    // a chain of four mixes), then one mix.
    const auto& w = key.words;
    const std::uint64_t h = (std::uint64_t{w[0]} << 32 | w[1]) * 0x9e3779b97f4a7c15ull ^
                            (std::uint64_t{w[2]} << 32 | w[3]) * 0xc2b2ae3d27d4eb4full ^
                            (std::uint64_t{w[4]} << 32 | w[5]) * 0x165667b19e3779f9ull ^ std::uint64_t{w[6]} * 0xd6e8feb86659fd93ull;
    return mix(h);
}

const CachedQuery* QueryCache::find(const QueryKey& key) const {
    if (m_slots.empty()) return nullptr;
    const Slot& slot = m_slots[hash(key) & (m_slots.size() - 1)];
    return slot.interval == m_interval && slot.key == key ? &slot.query : nullptr;
}

void QueryCache::insert(const QueryKey& key, const CachedQuery& query) {
    if (m_slots.empty()) m_slots.resize(k_slots);
    Slot& slot = m_slots[hash(key) & (m_slots.size() - 1)];
    if (slot.interval == m_interval && slot.key == key) return;  // stored already (the same result)
    m_used += slot.interval != m_interval;
    slot = {key, m_interval, query};
}

void QueryCache::next_interval() {
    m_used = 0;
    if (++m_interval == 0) {  // the stamps wrapped (after 2^32 - 1 intervals): clear them
        for (Slot& slot : m_slots) slot.interval = 0;
        m_interval = 1;
    }
}

}  // namespace collidescope::ccd
