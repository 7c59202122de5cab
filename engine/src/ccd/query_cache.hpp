#pragma once
// The primitive queries' results within one interval (engine/src/ccd, private), shared by the
// triangle pairs that ask the same query. On a mesh a vertex lies in about six triangles and an
// edge in two, so each vertex-face and edge-edge query is asked by several candidate pairs:
// about three times on average on the built-in meshes (demo, A, C, cloth-drape); never twice on
// a triangle soup, which does not use the cache. A stored result is a pure function of its key
// (the features, in a fixed order, and the query's form), so which pair solved it first changes
// nothing: one cache per thread (the walk gives each thread whole subtrees, so the pairs that
// share a feature mostly meet on one thread), no locks.

#include "ccd/inclusion.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace collidescope::ccd {

/// A query: its form (vertex-face, vertex-face in the plane dropping axis k, edge-edge) and
/// its features, each named by object and vertex or triangle indices.
struct QueryKey {
    std::array<std::uint32_t, 7> words{};
    /// Word by word, inline (the defaulted comparison called memcmp).
    friend bool operator==(const QueryKey& x, const QueryKey& y) {
        bool same = true;
        for (std::size_t i = 0; i < x.words.size(); ++i) same = same && x.words[i] == y.words[i];
        return same;
    }

    /// Vertex `v` of object `vertex_object` against triangle `tri` of `face_object`; `drop`:
    /// the planar form's axis, or -1.
    static QueryKey vertex_face(std::uint32_t vertex_object, std::uint32_t v, std::uint32_t face_object, std::uint32_t tri,
                                int drop);
    /// Edge (p0, p1) of `p_object` against edge (q0, q1) of `q_object`, each with its smaller
    /// vertex index first and the edges in (object, index) order (edge_edge's order).
    static QueryKey edge_edge(std::uint32_t p_object, std::uint32_t p0, std::uint32_t p1, std::uint32_t q_object,
                              std::uint32_t q0, std::uint32_t q1);
};

/// A stored query: cleared by its filter, or its solution.
struct CachedQuery {
    QueryResult result;
    bool cleared = false;
};

/// One thread's recent results: a direct-mapped table of 4096 slots (256 KiB), a later key
/// taking an earlier one's slot, each slot stamped with the interval it belongs to, so a new
/// interval clears nothing. The walk asks a feature's pairs close together (one subtree at a
/// time), so nearly every recurrence is found: on data set A and demo the instructions came
/// within 1% of an unbounded table's, which ran slower (its misses of the memory caches).
class QueryCache {
public:
    /// The stored result of `key` in this interval, or nullptr (never stored, or its slot taken).
    const CachedQuery* find(const QueryKey& key) const;
    void insert(const QueryKey& key, const CachedQuery& query);
    /// A new interval: every result stored so far is forgotten.
    void next_interval();
    /// Slots holding a result of this interval.
    std::size_t size() const { return m_used; }

private:
    struct Slot {
        QueryKey key;
        std::uint32_t interval = 0;  ///< 0: never used
        CachedQuery query;
    };
    static std::uint64_t hash(const QueryKey& key);
    static constexpr std::size_t k_slots = 4096;

    std::vector<Slot> m_slots;      ///< k_slots once the first result is stored
    std::size_t m_used = 0;         ///< slots of this interval
    std::uint32_t m_interval = 1;
};

}  // namespace collidescope::ccd
