#pragma once
/// Meshes and scenes for tests, built in memory from a seed: grid sheets (shared vertices and
/// edges), crumpled sheets that fold over themselves, soups of triangles snapped to a coarse
/// grid (so contacts are exact touches, coplanar overlaps and boxes that only touch), and
/// random multi-object scenes over several frames.

#include "collidescope/mesh.hpp"
#include "collidescope/scene.hpp"

#include <cstdint>
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
