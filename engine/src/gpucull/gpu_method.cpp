// Mode 2: GPU cull, final step over the survivors, exact narrow phase.

#include "gpucull/gpu_method.hpp"

#include "gpucull/cull_renderer.hpp"
#include "gpucull/gl_context.hpp"
#include "gpucull/image_space_cull.hpp"
#include "gpucull/final_hierarchy.hpp"
#include "pipeline/narrow_phase.hpp"
#include "pipeline/stopwatch.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <stdexcept>

namespace collidescope {
namespace {

using gpucull::PcsObject;

void check_config(const GpuCullConfig& config) {
    if (config.resolution < 1 || config.resolution > 8192) {
        throw std::invalid_argument("GPU cull resolution must be 1..8192, got " + std::to_string(config.resolution));
    }
    if (config.views.empty() || config.views.size() > 3 ||
        std::any_of(config.views.begin(), config.views.end(), [](int v) { return v < 0 || v > 2; })) {
        throw std::invalid_argument("GPU cull views must be one to three axes among 0, 1, 2");
    }
}

// Every object of an inter-object pair, ascending, with all its triangles.
std::vector<PcsObject> initial_pcs(const FrameContext& context) {
    std::vector<std::uint32_t> objects;
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a == pair.b) continue;
        objects.push_back(pair.a);
        objects.push_back(pair.b);
    }
    std::sort(objects.begin(), objects.end());
    objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
    std::vector<PcsObject> pcs;
    for (const std::uint32_t object : objects) {
        PcsObject entry{object, {}};
        entry.triangles.resize(context.frame.objects[object].triangle_count());
        for (std::uint32_t i = 0; i < entry.triangles.size(); ++i) entry.triangles[i] = i;
        pcs.push_back(std::move(entry));
    }
    return pcs;
}

class GpuMethod final : public Method {
public:
    explicit GpuMethod(const GpuCullConfig& config)
        : m_config((check_config(config), config)), m_context(gpucull::make_osmesa_context()) {}

    std::string_view name() const override { return "gpu"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        Stopwatch stopwatch;
        m_context->make_current();
        GpuFrameInfo info;
        info.renderer = m_context->renderer();
        std::vector<PcsObject> pcs = initial_pcs(context);
        gpucull::CullTimes times;
        gpucull::cull_pcs(context.frame, pcs, m_config, m_renderer, info, times);
        stats.ms.gpu_render += times.render;
        stats.ms.gpu_readback += times.readback;
        stopwatch.lap_ms();

        gpucull::FinalStepStats final_stats;
        const std::vector<TrianglePair> candidates = gpucull::final_step_candidates(context, pcs, final_stats);
        stats.counts.box_tests += final_stats.box_tests;
        stats.counts.nodes_visited += final_stats.nodes_visited;
        stats.ms.final_hierarchy += stopwatch.lap_ms();
        stats.ms.cull += times.render + times.readback + stats.ms.final_hierarchy;
        stats.counts.candidate_pairs += candidates.size();
        stats.gpu = std::move(info);
        narrow_phase(context.frame, candidates, pairs, stats);
    }

private:
    GpuCullConfig m_config;
    std::unique_ptr<gpucull::GlContext> m_context;  // before the renderer: it needs the context
    gpucull::CullRenderer m_renderer;
};

}  // namespace

std::unique_ptr<Method> make_gpu_method(const GpuCullConfig& config) {
    return std::make_unique<GpuMethod>(config);
}

}  // namespace collidescope
