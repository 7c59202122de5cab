#pragma once
// The cost policy's GPU prior (engine/src/decision, private): when the policy asks, a
// throwaway GPU cull with the run's options culls two interpenetrating wavy sheets at two
// sizes; a line through the two times gives the fixed and per-triangle cost. The thesis did
// the same by hand (Table 4.3: query and triangle test times benchmarked beforehand).

#include "decision/policy.hpp"

#include "collidescope/gpu_cull.hpp"


namespace collidescope::decision {

/// Measures the prior (four GPU frames: a few hundred ms under llvmpipe). Throws
/// UnavailableError without GL.
GpuCostPrior measure_gpu_prior(const GpuCullConfig& config);

}  // namespace collidescope::decision
