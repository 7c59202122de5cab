#pragma once
// What the penetration measure needs of a topology (engine/src/regions, private): whether it
// is closed, and each vertex's triangles. Computed once per topology revision and kept.

#include "collidescope/large_blocks.hpp"
#include "collidescope/scene.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace collidescope::regions {

struct MeshShape {
    /// Every edge is used by exactly two triangles, once in each direction (an edge-manifold
    /// surface without border, consistently oriented), and no triangle repeats a vertex.
    bool closed = false;
    /// Vertex v's triangles are incident[incident_begin[v] .. incident_begin[v + 1]) (large
    /// blocks once large: a big mesh's lists fault in a few huge pages).
    detail::LargeVector<std::uint32_t> incident_begin;
    detail::LargeVector<std::uint32_t> incident;
};

/// The shape of `topology`, from a small cache keyed by its revision (thread-safe).
std::shared_ptr<const MeshShape> mesh_shape(const Topology& topology);

}  // namespace collidescope::regions
