#pragma once
/// A collision method (engine/src/methods): culling plus the exact narrow phase, and the options
/// the methods read. The pipeline (collidescope/pipeline.hpp) makes one by name and runs it.

#include "collidescope/aabb_options.hpp"
#include "collidescope/adaptive_options.hpp"
#include "collidescope/frame_context.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/types.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

/// Options of one pipeline.
struct PipelineConfig {
    std::string method = "brute";  ///< a name from method_names()
    bool self_collision = false;   ///< also report pairs within one object (self-collision rule)
    /// Worker threads, >= 0; 0 = TBB's default (all hardware threads). The limit is a
    /// tbb::global_control held while the pipeline lives, so it is process-wide: with several
    /// pipelines alive at once, the smallest limit wins.
    int threads = 0;
    GpuCullConfig gpu;  ///< options of the GPU cull (methods gpu, ...)
    AabbOptions aabb;   ///< options of the AABB hierarchies (method aabb)
    AdaptiveOptions adaptive;  ///< options of the decision system (method adaptive)
};

/// A collision method: culling plus the exact narrow phase. Stateful across frames
/// (hierarchies, GPU state); frames arrive in order.
class Method {
public:
    virtual ~Method() = default;
    virtual std::string_view name() const = 0;
    /// Appends every colliding pair among context.object_pairs to `pairs` (canonical order
    /// within a pair, any order between pairs; the pipeline sorts) and fills the method's
    /// fields of `stats`: ms.cull, ms.narrow (and its breakdown), counts.box_tests,
    /// candidate_pairs, exact_tests, exact_fallbacks and colliding_pairs.
    virtual void detect(const FrameContext& context, std::vector<TrianglePair>& pairs,
                        FrameStats& stats) = 0;
};

}  // namespace collidescope
