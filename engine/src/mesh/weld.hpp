#pragma once
// Welding: vertices with equal keys become one vertex (engine/src/mesh, private).
//
// Importers split a vertex wherever its normal or texture coordinate changes (a seam), so
// corners that are one point of the surface carry different indices and the self-collision
// rule (DESIGN.md) would report the triangles around a seam as touching neighbours. Every
// mesh read through assimp is welded: two vertices of one mesh become one when their keys are
// equal, the key being whatever decides where a vertex lands in every frame (its position;
// for an animated mesh also its morph targets and its normalised bone influences). Equal
// inputs go through the same arithmetic, so welded vertices coincide in every frame exactly.

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope {

/// Per-vertex keys, flattened: vertex v's key is values[begin[v] .. begin[v + 1]).
struct WeldKeys {
    std::vector<double> values;
    std::vector<std::uint32_t> begin{0};  ///< size vertex count + 1

    /// Appends one vertex's key.
    void add(std::span<const double> key) {
        values.insert(values.end(), key.begin(), key.end());
        begin.push_back(static_cast<std::uint32_t>(values.size()));
    }
    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(begin.size() - 1); }
};

/// The result: `remap[v]` is old vertex v's new index; `kept[n]` the old index of new vertex n
/// (the first vertex of its group). New vertices keep the order of their first occurrence.
struct Welding {
    std::vector<std::uint32_t> remap;
    std::vector<std::uint32_t> kept;
};

/// Groups vertices whose keys are equal value for value (-0 equals +0; NaN equals only a NaN
/// with the same bits, so a bad key never breaks the ordering). O(n log n).
Welding weld(const WeldKeys& keys);

}  // namespace collidescope
