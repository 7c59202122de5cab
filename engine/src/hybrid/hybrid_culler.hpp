#pragma once
// The AABB + GPU cull framework (engine/src/hybrid, private; thesis 4.3, Figure 4.7): the AABB
// traversal goes down to the leaves and, instead of testing triangle pairs, marks the
// triangles involved (A); the GPU culls the marked set (B); the survivors percolate up the
// trees (C); the final traversal runs on the culled trees (D). Self-collision pairs skip the
// GPU (the cull is inter-object) and go straight to the candidates. analyse() gives the
// quantities of the thesis's analysis (Equations 4.11-4.17). No narrow phase: the `hybrid`
// method (engine/src/methods) adds it between cull() and analyse().

#include "bvh/aabb_culler.hpp"
#include "gpucull/cull_context.hpp"
#include "gpucull/cull_renderer.hpp"
#include "gpucull/view_configuration.hpp"

#include "collidescope/frame_context.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/stats.hpp"

#include <memory>
#include <span>
#include <vector>

namespace collidescope::hybrid {

/// The framework over an AABB culler (shared with other methods, e.g. by `adaptive`, so the
/// trees stay warm) with its own GL context. Stateful across frames (the view matrix learns;
/// the unit costs of the analysis are kept across frames without measurements).
class HybridCuller {
public:
    /// Throws UnavailableError when no GL context can be made.
    HybridCuller(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu);
    // The renderer deletes its GL objects in the current context: the destructor makes it ours.
    ~HybridCuller();
    HybridCuller(const HybridCuller&) = delete;
    HybridCuller& operator=(const HybridCuller&) = delete;

    /// Steps A to D: sets `candidates` to the pairs that reach the exact test, fills `info`'s
    /// counts (a1, a2, tri_1, tri_r, tri_2), the stage times and counts of `stats` and
    /// stats.gpu. Returns the first traversal's stats (its ms: the AABB detection time's
    /// first part).
    bvh::TraversalStats cull(const FrameContext& context, std::vector<TrianglePair>& candidates,
                             HybridFrameInfo& info, FrameStats& stats);
    /// Equations 4.11-4.17 with this frame's measured unit costs (A_I per node test of the
    /// first traversal, T_I per exact test: call it after the narrow phase filled `stats`; O
    /// per rendered triangle: the thesis counts one query per triangle, stats.gpu.query_ms
    /// keeps the cost per query).
    void analyse(HybridFrameInfo& info, double traversal_ms, const FrameStats& stats);
    /// The AABB culler (its clock times the narrow phase; its rebuild rule needs the detection time).
    bvh::AabbCuller& aabb() { return *m_culler; }

private:
    void cull_and_retraverse(const FrameContext& context, std::span<const TrianglePair> inter,
                             std::vector<TrianglePair>& candidates, HybridFrameInfo& info, FrameStats& stats);

    std::shared_ptr<bvh::AabbCuller> m_culler;
    GpuCullConfig m_config;
    gpucull::ViewConfiguration m_views;
    std::unique_ptr<gpucull::GlContext> m_context;  // before the renderer: it needs the context
    gpucull::CullRenderer m_renderer;
    double m_gpu_ms = 0;
    double m_t_i = 0;  // last measured, kept across frames without exact tests
    double m_o = 0;
};

}  // namespace collidescope::hybrid
