#pragma once
// The `gpu` and `gpu-naive` methods (Mode 2, thesis 4.2; engine/src/methods): the GPU culling
// (gpucull/gpu_culler.hpp), then the shared exact narrow phase.

#include "collidescope/gpu_cull.hpp"
#include "collidescope/method.hpp"

#include <memory>

namespace collidescope {

/// Makes the `gpu` method (or `gpu-naive` when config.naive) with its own GL context. Throws
/// UnavailableError with the reason when no context can be made.
std::unique_ptr<Method> make_gpu_method(const GpuCullConfig& config);

}  // namespace collidescope
