// Pipeline::process: update, object level, the method, sort and unique, report.

#include "collidescope/pipeline.hpp"

#include "stages/object_level.hpp"
#include "stages/pair_order.hpp"
#include "stats/stopwatch.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace collidescope {
namespace {

/// Sorts pairs in TrianglePair's order (stages/pair_order.hpp: a radix sort where the indices
/// fit one word, else a comparison sort on TBB's threads; duplicates, which unique removes
/// after, are equal values, so their order does not matter).
void sort_pairs(std::vector<TrianglePair>& pairs) {
    sort_by_pair(pairs, [](const TrianglePair& p) -> const TrianglePair& { return p; });
}

}  // namespace

/// Caps TBB's worker threads while it lives (process-wide, see PipelineConfig::threads).
class ThreadLimit {
public:
    explicit ThreadLimit(int threads)
        : m_control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads)) {}

private:
    tbb::global_control m_control;
};

Pipeline::Pipeline(PipelineConfig config) : m_config(std::move(config)) {
    if (m_config.threads < 0) {
        throw std::invalid_argument("threads must be >= 0, got " + std::to_string(m_config.threads));
    }
    m_method = make_method(m_config.method, m_config);
    if (m_config.threads > 0) m_thread_limit = std::make_unique<ThreadLimit>(m_config.threads);
}

Pipeline::~Pipeline() = default;

void Pipeline::add_sink(TraceSink& sink) { m_sinks.push_back(&sink); }

FrameResult Pipeline::process(const Frame& frame) {
    const Stopwatch total;
    Stopwatch stage;
    FrameResult result;
    FrameStats& stats = result.stats;
    stats.frame = frame.index;
    stats.method = std::string(m_method->name());

    // 1. Update: the frame's new positions are in `frame`; object boxes.
    const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
    for (const ObjectFrame& object : frame.objects) {
        assert(object.vertices.size() == object.topology->vertex_count);
        stats.counts.triangles += object.triangle_count();
    }
    stats.counts.positions_copied_bytes = frame.positions_copied_bytes;
    stats.ms.update = stage.lap_ms();

    // 2. Object level.
    const std::vector<ObjectPair> object_pairs = find_object_pairs(boxes, m_config.self_collision);
    stats.counts.object_pairs = object_pairs.size();
    stats.ms.object_level = stage.lap_ms();

    // 3 + 4. The method's culling and narrow phase; then one canonical, sorted list.
    const FrameContext context{frame, boxes, object_pairs, m_config.self_collision};
    m_method->detect(context, result.colliding_pairs, stats);
    sort_pairs(result.colliding_pairs);
    result.colliding_pairs.erase(
        std::unique(result.colliding_pairs.begin(), result.colliding_pairs.end()),
        result.colliding_pairs.end());
    stats.counts.colliding_pairs = result.colliding_pairs.size();
    stats.ms.total = total.elapsed_ms();

    const FrameReport report{frame, stats, result.colliding_pairs};
    for (TraceSink* sink : m_sinks) sink->on_frame(report);
    return result;
}

}  // namespace collidescope
