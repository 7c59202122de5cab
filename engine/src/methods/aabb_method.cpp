// The `aabb` method's frame: the AABB culling, then the narrow phase, timed for the rebuild rule.

#include "methods/aabb_method.hpp"

#include "stages/narrow_phase.hpp"

namespace collidescope {
namespace {

class AabbMethod final : public Method {
public:
    explicit AabbMethod(std::shared_ptr<bvh::AabbCuller> culler) : m_culler(std::move(culler)) {}

    std::string_view name() const override { return "aabb"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        m_candidates.clear();  // kept from frame to frame: its memory is reused
        const bvh::TraversalStats traversal = m_culler->cull(context, m_candidates, stats);
        const double before = m_culler->now();
        narrow_phase(context.frame, m_candidates, pairs, stats);
        m_culler->set_detection_ms(traversal.ms + (m_culler->now() - before), traversal.ms);
    }

private:
    std::shared_ptr<bvh::AabbCuller> m_culler;
    std::vector<TrianglePair> m_candidates;
};

}  // namespace

std::unique_ptr<Method> make_aabb_method(bvh::AabbConfig config) {
    return make_aabb_method(std::make_shared<bvh::AabbCuller>(std::move(config)));
}

std::unique_ptr<Method> make_aabb_method(std::shared_ptr<bvh::AabbCuller> culler) {
    return std::make_unique<AabbMethod>(std::move(culler));
}

}  // namespace collidescope
