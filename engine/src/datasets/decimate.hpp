#pragma once
// Vertex-clustering decimation (Rossignac and Borrel 1993) for the small and default presets
// of the mesh data sets (engine/src/datasets, private).

#include "collidescope/mesh.hpp"

#include <cstdint>

namespace collidescope::datasets {

/// Simplifies `mesh` by snapping its vertices to a uniform grid of cubic cells, `cells` cells
/// along the longest side of its bounding box: each occupied cell becomes one vertex (the mean
/// of its members), triangles whose corners fall into fewer than three cells are dropped, and
/// of triangles with the same three cells only the first is kept. Deterministic: output
/// vertices are numbered in order of first use by a kept triangle, kept triangles stay in input
/// order, and unused vertices are dropped. `cells` >= 1.
MeshData decimate(const MeshData& mesh, std::uint32_t cells);

}  // namespace collidescope::datasets
