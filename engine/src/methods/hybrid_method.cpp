// The `hybrid` method's frame: the framework's culling, the narrow phase, the analysis.

#include "methods/hybrid_method.hpp"

#include "stages/narrow_phase.hpp"
#include "hybrid/hybrid_culler.hpp"

namespace collidescope {
namespace {

class HybridMethod final : public Method {
public:
    HybridMethod(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu)
        : m_culler(std::move(culler), gpu) {}

    std::string_view name() const override { return "hybrid"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        HybridFrameInfo info;
        std::vector<TrianglePair> candidates;
        const bvh::TraversalStats traversal = m_culler.cull(context, candidates, info, stats);
        bvh::AabbCuller& aabb = m_culler.aabb();
        const double before = aabb.now();
        narrow_phase(context.frame, candidates, pairs, stats);
        aabb.set_detection_ms(traversal.ms + (aabb.now() - before), traversal.ms);
        m_culler.analyse(info, traversal.ms, stats);
        stats.hybrid = info;
    }

private:
    hybrid::HybridCuller m_culler;
};

}  // namespace

std::unique_ptr<Method> make_hybrid_method(std::shared_ptr<bvh::AabbCuller> culler, const GpuCullConfig& gpu) {
    return std::make_unique<HybridMethod>(std::move(culler), gpu);
}

}  // namespace collidescope
