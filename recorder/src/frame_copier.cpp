// Copies a frame off the engine's spans for the writer thread.

#include "frame_copier.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/stats.hpp"

#include <algorithm>
#include <span>

namespace collidescope::recorder {
namespace {

// Runs on the engine's thread inside on_frame: the frame's vertices may view the caller's
// memory (Session::step), valid only until the step returns, so the writer thread gets this copy.
LargeVector<float> to_float(std::span<const Vec3> vertices) {
    LargeVector<float> out(vertices.size() * 3);
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (int axis = 0; axis < 3; ++axis) out[3 * v + static_cast<std::size_t>(axis)] = static_cast<float>(vertices[v][axis]);
    }
    return out;
}

// The methods' own details (schema 1.1 and 1.2): zeros and present = 0 when a method has none.
void copy_details(const FrameStats& stats, FrameRecord& record) {
    record.has_gpu = stats.gpu.has_value();
    for_each_gpu_value(stats.gpu.value_or(GpuFrameInfo{}), [&](const char*, double v, const char*) { record.gpu.push_back(v); });
    if (stats.gpu) {
        for (const GpuPassInfo& pass : stats.gpu->passes) {
            for_each_pass_field(pass, [&](const char*, std::uint64_t v) { record.gpu_passes.push_back(v); });
        }
        record.survivors.assign(stats.gpu->survivors.begin(), stats.gpu->survivors.end());
        record.depth_images = stats.gpu->depth_images;
    }
    record.has_aabb = stats.aabb.has_value();
    for_each_aabb_value(stats.aabb.value_or(AabbFrameInfo{}), [&](const char*, double v, const char*) { record.aabb.push_back(v); });
    record.has_decision = stats.decision.has_value();
    for_each_decision_value(stats.decision.value_or(DecisionInfo{}),
                            [&](const char*, double v, const char*) { record.decision.push_back(v); });
    record.has_hybrid = stats.hybrid.has_value();
    for_each_hybrid_value(stats.hybrid.value_or(HybridFrameInfo{}),
                          [&](const char*, double v, const char*) { record.hybrid.push_back(v); });
}

}  // namespace

FrameCopier::FrameCopier(std::string file) : m_file(std::move(file)), m_methods(method_names()) {
    if (m_methods.size() > 255) throw InputError("too many methods for the recording's enum");
}

FrameRecord FrameCopier::copy(const FrameReport& report) {
    FrameRecord record;
    record.frame = report.frame.index;
    const auto code = std::find(m_methods.begin(), m_methods.end(), report.stats.method);
    if (code == m_methods.end()) throw InputError(m_file + ": unknown method " + report.stats.method);
    record.method = static_cast<std::uint8_t>(code - m_methods.begin());
    for_each_stage(report.stats.ms, [&](const char*, double value) { record.ms.push_back(value); });
    for_each_count(report.stats.counts, [&](const char*, std::uint64_t value) { record.counts.push_back(value); });
    record.pairs.assign(report.colliding_pairs.begin(), report.colliding_pairs.end());
    copy_details(report.stats, record);
    if (m_first) m_revisions.assign(report.frame.objects.size(), 0);
    for (std::size_t k = 0; k < report.frame.objects.size(); ++k) {
        const ObjectFrame& object = report.frame.objects[k];
        ObjectRecord out;
        if (m_first || object.topology->revision != m_revisions[k]) {
            out.new_topology = object.topology;
            m_revisions[k] = object.topology->revision;
        }
        out.positions = to_float(object.vertices);
        record.objects.push_back(std::move(out));
    }
    m_first = false;
    return record;
}


}  // namespace collidescope::recorder
