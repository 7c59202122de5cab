#pragma once
// What the generated scenes share (engine/src/datasets, private): a closed UV sphere and an
// open tube, as topologies and as unit shapes to place per frame; the time and grid helpers
// of the cloth and contact families.

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"

#include "collidescope/types.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace collidescope::datasets {

/// Frame `frame` of `frames` as a time in [0, 1] (0 for a single frame).
inline double frame_time(std::uint32_t frame, std::uint32_t frames) {
    return frames > 1 ? static_cast<double>(frame) / (frames - 1) : 0.0;
}

/// Coordinate i of n evenly spaced values over [lo, hi].
inline double lerp_grid(std::uint32_t i, std::uint32_t n, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(i) / (n - 1);
}

/// 0 below edge0, 1 above edge1, and the cubic 3s^2 - 2s^3 of s = (x - edge0) / (edge1 - edge0)
/// between: an ease in and out.
inline double smoothstep(double edge0, double edge1, double x) {
    const double s = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return s * s * (3 - 2 * s);
}

/// A scene of the cloth or contact family (self-collision on) over its generated objects.
inline Scene family_scene(const char* name, Preset preset, std::uint64_t seed,
                          std::vector<GeneratedObject> objects, std::uint32_t frames) {
    return {name, preset_name(preset), seed, true, make_generated_source(std::move(objects), frames)};
}

/// The preset's choice among three sizes.
inline std::uint32_t pick(Preset preset, std::uint32_t small, std::uint32_t normal, std::uint32_t large) {
    return preset == Preset::Small ? small : preset == Preset::Default ? normal : large;
}

/// A closed UV sphere without pole singularities in its indexing: `rings` latitude rings of
/// `segments` vertices (closed in longitude), plus one vertex at each pole with a fan.
/// segments * rings + 2 vertices, 2 segments rings triangles.
std::vector<TriIndices> sphere_triangles(std::uint32_t segments, std::uint32_t rings);

/// The unit sphere's vertices in sphere_triangles' order (ring r at polar angle
/// pi (r + 1) / (rings + 1) from the south pole; the south pole, then the north pole, last).
void unit_sphere_vertices(std::uint32_t segments, std::uint32_t rings, std::span<Vec3> out);

/// An open tube: `around` vertices per ring (closed around), `along` rings, ring k's vertices at
/// indices k * around ... k * around + around - 1. 2 around (along - 1) triangles.
std::vector<TriIndices> tube_triangles(std::uint32_t around, std::uint32_t along);

}  // namespace collidescope::datasets
