#pragma once
// The image-space cull of the thesis's Mode 2 (engine/src/gpucull, private; thesis 3.2 and 4.2,
// CULLIDE with Quick-CULLIDE's two passes): the potentially colliding set (PCS) of objects,
// then of triangles, over up to three axis-aligned orthographic views fitted to the current
// PCS, each with a forward and a reverse pass. An item fully visible in both passes of a view
// is in front of every other object's PCS triangle wherever they overlap in that view, so it
// touches none of them, and it leaves the PCS. Inter-object only: self-collision pairs are
// left to the final step.

#include "gpucull/cull_renderer.hpp"

#include "collidescope/gpu_cull.hpp"
#include "collidescope/scene.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope::gpucull {

/// The triangles of one object still in the PCS.
struct PcsObject {
    std::uint32_t object = 0;
    std::vector<std::uint32_t> triangles;  ///< ascending
};

/// What one frame's cull does: the configuration with this frame's choices filled in (the
/// views from the view configuration matrix, P from the triangles-per-query mechanism).
struct CullPlan {
    int resolution = 256;
    std::vector<int> views = {2, 0, 1};   ///< axes, in order
    std::uint32_t triangles_per_query = 1;
    GpuCullVariant variant = GpuCullVariant::Queries;
    bool object_level = true;
    bool sort_objects = true;             ///< front to back along each view (thesis 4.2.2)
    /// Read back the depth buffer after the forward pass of each triangle-level view into
    /// GpuFrameInfo::depth_images (GpuCullConfig::depth_every; the read back counts as readback).
    bool capture_depth = false;
};

/// Milliseconds of the cull: issuing draws, and waiting for query results or flags.
struct CullTimes {
    double render = 0;
    double readback = 0;
};

/// Culls `pcs` (objects in ascending order, each with its candidate triangles) in place:
/// objects and triangles that provably touch no other object's PCS triangle are removed;
/// objects left with no triangle, or alone, are removed. Fills `info`.
void cull_pcs(const Frame& frame, std::vector<PcsObject>& pcs, const CullPlan& plan,
              CullRenderer& renderer, GpuFrameInfo& info, CullTimes& times);

}  // namespace collidescope::gpucull
