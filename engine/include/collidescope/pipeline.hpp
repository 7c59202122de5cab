#pragma once
/// The per-frame pipeline (engine/src/pipeline): update, object level, the method's culling
/// and narrow phase, then the report to the trace sinks.

#include "collidescope/aabb_options.hpp"
#include "collidescope/adaptive_options.hpp"
#include "collidescope/frame_context.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/scene.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/trace.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <memory>
#include <span>
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

/// The names `--method` accepts, in a stable order.
std::vector<std::string> method_names();

/// Makes a method by name, with the options `config` holds for it. Throws
/// std::invalid_argument, listing the known names, on an unknown name, and UnavailableError
/// (with the reason) when the method needs a capability the machine lacks (a GL context).
std::unique_ptr<Method> make_method(std::string_view name, const PipelineConfig& config = {});

/// The result of one frame.
struct FrameResult {
    std::vector<TrianglePair> colliding_pairs;  ///< sorted, unique
    FrameStats stats;
};

class ThreadLimit;

/// Runs frames through a method and reports each to the sinks. One thread calls it; the
/// method parallelises inside a frame.
class Pipeline {
public:
    /// Throws std::invalid_argument on an unknown method or a negative thread count.
    explicit Pipeline(PipelineConfig config);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    /// Adds a sink; it must outlive the pipeline's use.
    void add_sink(TraceSink& sink);
    /// Processes one frame (frames in order): update, object level, the method, sort and
    /// unique; then reports it to every sink. ms.total covers everything but the sinks.
    FrameResult process(const Frame& frame);
    const PipelineConfig& config() const { return m_config; }

private:
    PipelineConfig m_config;
    std::unique_ptr<Method> m_method;
    std::vector<TraceSink*> m_sinks;
    std::unique_ptr<ThreadLimit> m_thread_limit;  ///< null when threads == 0
};

}  // namespace collidescope
