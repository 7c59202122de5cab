#pragma once
/// The per-frame pipeline (engine/src/pipeline, the engine's top layer): update, object level,
/// the method's culling and narrow phase, then the report to the trace sinks; and the method
/// registry (make_method by name).

#include "collidescope/method.hpp"
#include "collidescope/scene.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/trace.hpp"
#include "collidescope/types.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

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
