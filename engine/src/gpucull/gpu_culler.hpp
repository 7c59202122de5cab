#pragma once
// Mode 2's culling (thesis 4.2, "Perform GPU 2"; engine/src/gpucull, private): the objects of
// inter-object pairs go through the image-space cull, the survivors through the final step
// (final_hierarchy: a hierarchy over the survivors). Self-collision pairs skip the GPU (the
// cull is inter-object) and come from the final step over the whole object. No narrow phase:
// the `gpu` and `gpu-naive` methods (engine/src/methods) add it.

#include "gpucull/cull_context.hpp"
#include "gpucull/cull_renderer.hpp"
#include "gpucull/image_space_cull.hpp"
#include "gpucull/triangles_per_query.hpp"
#include "gpucull/view_configuration.hpp"

#include "collidescope/frame_context.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/stats.hpp"

#include <memory>
#include <random>
#include <vector>

namespace collidescope::gpucull {

/// The GPU cull with its mechanisms (the view configuration matrix, Algorithm 2; adaptive
/// triangles per query, Algorithm 3), or the naive baseline (config.naive: random views, one
/// triangle per query), with its own GL context. Stateful across frames (the mechanisms learn).
class GpuCuller {
public:
    /// Throws std::invalid_argument on a bad resolution or view list, UnavailableError with
    /// the reason when no GL context can be made.
    explicit GpuCuller(const GpuCullConfig& config);
    // The renderer deletes its GL objects in the current context: the destructor makes it ours.
    ~GpuCuller();
    GpuCuller(const GpuCuller&) = delete;
    GpuCuller& operator=(const GpuCuller&) = delete;

    /// The frame's candidate pairs (canonical) after the GPU cull and the final step. Fills
    /// ms.gpu_render, gpu_readback, final_hierarchy and cull, counts.box_tests,
    /// nodes_visited and candidate_pairs, and stats.gpu.
    std::vector<TrianglePair> cull(const FrameContext& context, FrameStats& stats);

    const GpuCullConfig& config() const { return m_config; }

private:
    CullPlan frame_plan();
    void learn(const CullPlan& plan, GpuFrameInfo& info, const CullTimes& times, double final_ms);

    GpuCullConfig m_config;
    ViewConfiguration m_views;
    TrianglesPerQuery m_per_query;
    std::mt19937_64 m_random;
    std::unique_ptr<GlContext> m_context;  // before the renderer: it needs the context
    CullRenderer m_renderer;
};

}  // namespace collidescope::gpucull
