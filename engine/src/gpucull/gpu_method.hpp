#pragma once
// The `gpu` method (engine/src/gpucull): Mode 2 of the thesis ("Perform GPU 2"): the objects of
// inter-object pairs go through the image-space cull, the survivors through the final step
// (final_hierarchy: a hierarchy over the survivors), then the exact narrow phase. Self-collision
// pairs skip the GPU (the cull is inter-object) and come from the final step over the whole
// object.

#include "collidescope/gpu_cull.hpp"
#include "collidescope/pipeline.hpp"

#include <memory>

namespace collidescope {

/// Makes the `gpu` method (or `gpu-naive` when config.naive) with its own GL context (OSMesa). Throws UnavailableError with the
/// reason when no context can be made.
std::unique_ptr<Method> make_gpu_method(const GpuCullConfig& config);

}  // namespace collidescope
