#pragma once
// The `hybrid` method (the AABB + GPU cull framework, thesis 4.3; engine/src/methods): the
// framework's culling (hybrid/hybrid_culler.hpp), the shared exact narrow phase, then the
// framework's analysis (Equations 4.11-4.17) in stats.hybrid.

#include "bvh/aabb_culler.hpp"

#include "collidescope/gpu_cull.hpp"
#include "collidescope/method.hpp"

#include <memory>

namespace collidescope {

/// Makes the `hybrid` method over `culler` (its own, or shared with other methods, as the
/// `adaptive` method's are, so the trees stay warm) with its own GL context. Throws
/// UnavailableError without GL.
std::unique_ptr<Method> make_hybrid_method(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu);

}  // namespace collidescope
