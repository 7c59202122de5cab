#pragma once
// The AABB + GPU cull framework (engine/src/hybrid, private; thesis 4.3, Figure 4.7): the AABB
// traversal goes down to the leaves and, instead of testing triangle pairs, marks the
// triangles involved (A); the GPU culls the marked set (B); the survivors percolate up the
// trees (C); the final traversal runs on the culled trees (D), then the exact narrow phase.
// Self-collision pairs skip the GPU (the cull is inter-object) and go straight to the exact
// test. Reports the quantities of the thesis's analysis (Equations 4.11-4.17) in stats.hybrid.

#include "bvh/aabb_method.hpp"

#include "collidescope/gpu_cull.hpp"
#include "collidescope/pipeline.hpp"

#include <memory>

namespace collidescope::hybrid {

/// Makes the `hybrid` method over `culler` (shared with other methods, e.g. by `adaptive`,
/// so the trees stay warm) with its own GL context. Throws UnavailableError without GL.
std::unique_ptr<Method> make_hybrid_method(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu);

}  // namespace collidescope::hybrid
