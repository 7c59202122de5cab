#pragma once
// Splitting polygons into triangles (engine/src/mesh, private).
//
// Every reader splits a polygon with corners (v0, v1, ..., vn-1) as the fan (v0, vi, vi+1),
// i = 1..n-2, in that order, so triangle ids count the resulting triangles in file order.
// (assimp's aiProcess_Triangulate is not used: it rotates corners, even of triangles, and
// starts quads at a concave corner.)

#include "collidescope/types.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope {

/// Appends the fan of a polygon with at least three corners.
inline void append_fan(std::span<const std::uint32_t> corners, std::vector<TriIndices>& triangles) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        triangles.push_back({corners[0], corners[i], corners[i + 1]});
    }
}

}  // namespace collidescope
