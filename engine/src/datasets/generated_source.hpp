#pragma once
// Generated scenes (engine/src/datasets, private): a FrameSource that computes each frame's
// vertices on demand, and the small building blocks every generator shares (a portable seeded
// random stream, float32 rounding, grid and soup topologies).
//
// Determinism: a generator computes in double from its seed alone, and the source rounds every
// coordinate to the nearest float32 (kept as double), so a float32 PLY export holds exactly
// the coordinates the engine saw. Nothing here depends on the standard library's random
// distributions, whose output differs between implementations.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace collidescope::datasets {

/// A topology in force from `first_frame` until the next phase's first frame.
struct TopologyPhase {
    std::uint32_t first_frame = 0;
    std::shared_ptr<const Topology> topology;
};

/// Computes one object's vertices at `frame` into `out`, which holds exactly the vertex count
/// of the topology in force at that frame. Must be pure: the same frame gives the same
/// values, whatever was asked before (frames may be requested in any order).
using VertexFunction = std::function<void(std::uint32_t frame, std::span<Vec3> out)>;

/// One object of a generated scene.
struct GeneratedObject {
    std::string name;
    std::vector<TopologyPhase> phases;  ///< sorted by first_frame; the first starts at frame 0
    VertexFunction vertices;            ///< positions per frame, before float32 rounding
};

/// A FrameSource over `objects`: frame(i) calls each object's VertexFunction (O(vertices)),
/// rounds the result to float32 and hands out the phase's shared Topology, so the topology
/// revision changes exactly at phase boundaries. Checks the phases (asserts).
std::shared_ptr<FrameSource> make_generated_source(std::vector<GeneratedObject> objects,
                                                   std::uint32_t frame_count);

/// A Topology with a process-unique revision (scene/file_source's counter).
std::shared_ptr<const Topology> make_topology(std::vector<TriIndices> triangles,
                                              std::uint32_t vertex_count);

/// The triangles of a (columns x rows)-vertex grid, vertex (i, j) at index j * columns + i;
/// each cell split along its diagonal from (i, j) to (i + 1, j + 1); cells row by row.
/// 2 (columns - 1) (rows - 1) triangles.
std::vector<TriIndices> grid_triangles(std::uint32_t columns, std::uint32_t rows);

/// The same grid closed in both directions (a torus): column columns-1 joins column 0 and
/// row rows-1 joins row 0. 2 columns rows triangles.
std::vector<TriIndices> torus_triangles(std::uint32_t columns, std::uint32_t rows);

/// A triangle soup of `count` triangles: triangle i uses vertices 3i, 3i+1, 3i+2, so no two
/// triangles share a vertex (no edge connectivity).
std::vector<TriIndices> soup_triangles(std::uint32_t count);

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny seeded stream, identical on every platform.
class Random {
public:
    /// A stream for `seed`; `stream` separates independent uses of one seed.
    explicit Random(std::uint64_t seed, std::uint64_t stream = 0);

    std::uint64_t next_u64();
    /// Uniform in [0, 1), 53 random bits.
    double uniform();
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi);
    /// A point uniform in the cube [-1, 1)^3.
    Vec3 in_cube();
    /// A direction uniform on the unit sphere (rejection sampling in the unit ball).
    Vec3 unit_vector();
    /// A point uniform in the ball of radius `radius` around the origin.
    Vec3 in_ball(double radius);

private:
    std::uint64_t m_state;
};

}  // namespace collidescope::datasets
