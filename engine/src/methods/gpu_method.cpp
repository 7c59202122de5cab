// The `gpu` method's frame: the GPU culling, then the narrow phase.

#include "methods/gpu_method.hpp"

#include "stages/narrow_phase.hpp"
#include "gpucull/gpu_culler.hpp"

namespace collidescope {
namespace {

class GpuMethod final : public Method {
public:
    explicit GpuMethod(const GpuCullConfig& config) : m_culler(config) {}

    std::string_view name() const override { return m_culler.config().naive ? "gpu-naive" : "gpu"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        const std::vector<TrianglePair> candidates = m_culler.cull(context, stats);
        narrow_phase(context.frame, candidates, pairs, stats);
    }

private:
    gpucull::GpuCuller m_culler;
};

}  // namespace

std::unique_ptr<Method> make_gpu_method(const GpuCullConfig& config) {
    return std::make_unique<GpuMethod>(config);
}

}  // namespace collidescope
