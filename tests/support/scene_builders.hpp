#pragma once
/// Meshes and scenes for tests, built in memory from a seed: grid sheets (shared vertices and
/// edges), crumpled sheets that fold over themselves, soups of triangles snapped to a coarse
/// grid (so contacts are exact touches, coplanar overlaps and boxes that only touch), and
/// random multi-object scenes over several frames.

#include "collidescope/mesh.hpp"
#include "collidescope/scene.hpp"

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

namespace collidescope::testing {

/// A flat (cells x cells) grid in the plane z = `origin.z`, from `origin` to origin + (size,
/// size, 0); two triangles per cell, vertices shared between neighbours.
MeshData grid_sheet(std::uint32_t cells, double size, const Vec3& origin = Vec3::Zero());

/// A grid sheet whose vertices get random heights from {-1, 0, 1} * `amplitude` (and, with
/// `jitter`, moves of a quarter cell in x and y, on a grid): with an amplitude about a cell's
/// size, neighbouring triangles fold over each other, which exercises the self-collision rule
/// on triangles that share vertices and edges.
MeshData crumpled_sheet(std::mt19937_64& rng, std::uint32_t cells, double amplitude, bool jitter);

/// `triangles` triangles with corners on the integer grid [0, extent]^3 times `scale`,
/// sometimes degenerate (a repeated corner), vertices not shared.
MeshData grid_soup(std::mt19937_64& rng, std::uint32_t triangles, int extent, double scale = 1.0);

/// A (columns x rows)-cell grid surface with vertex (i, j) at place(i / columns, j / rows),
/// two triangles per cell, consistently oriented (shared vertices and edges).
MeshData surface_grid(std::uint32_t columns, std::uint32_t rows, const std::function<Vec3(double, double)>& place);

/// A ramp winding `turns` times about the z axis between radii 1 and 2, at height
/// height(angle) (angle in radians from 0): every triangle projects onto the xy plane with
/// the same orientation, yet after a turn the ramp lies over itself, so its outline does not
/// project to a simple polygon. height = 0: a coplanar double cover; crossing layers pierce.
MeshData helix_ramp(double turns, const std::function<double(double)>& height, std::uint32_t segments_per_turn = 24);

/// A flat (cells x cells) grid sheet in the plane z = 0 with a slit along x = cells / 2 from
/// the edge y = 0 for `slit` cells: the vertices on the slit but its inner end are duplicated
/// for the triangles on its right, so the two lips touch along the slit by position only.
MeshData slit_sheet(std::uint32_t cells, std::uint32_t slit);

/// Copies `mesh` moved by `offset`.
MeshData translated(MeshData mesh, const Vec3& offset);

/// Sizes of random_scene.
struct RandomSceneConfig {
    std::uint32_t objects = 3;         ///< objects per frame
    std::uint32_t frames = 2;          ///< frames; objects drift between them
    std::uint32_t max_triangles = 40;  ///< per soup object (at least 4)
    std::uint32_t sheet_cells = 5;     ///< per crumpled-sheet object
};

/// A random scene: each object is a grid soup or a crumpled sheet (chosen by the seed),
/// placed so that objects often touch and overlap, moving a grid step or two per frame.
/// Deterministic for a seed. Self-collision off (tests choose).
Scene random_scene(std::uint64_t seed, const RandomSceneConfig& config = {});

/// A one-frame scene of `meshes` (objects "object0", ...), as a memory source's frame 0.
Frame make_frame(std::vector<MeshData> meshes);

/// Every frame of `scene`, in order.
std::vector<Frame> all_frames(const Scene& scene);

}  // namespace collidescope::testing
