// The methods `--method` accepts, by name. A new method adds one line to k_methods.

#include "bvh/aabb_culler.hpp"
#include "methods/aabb_method.hpp"
#include "methods/adaptive_method.hpp"
#include "methods/brute_method.hpp"
#include "methods/gpu_method.hpp"
#include "methods/hybrid_method.hpp"

#include "collidescope/pipeline.hpp"

#include <stdexcept>

namespace collidescope {
namespace {

// A method under another registry name (a configuration of it): stats say which one ran.
class NamedMethod final : public Method {
public:
    NamedMethod(std::string_view name, std::unique_ptr<Method> inner) : m_name(name), m_inner(std::move(inner)) {}
    std::string_view name() const override { return m_name; }
    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        m_inner->detect(context, pairs, stats);
    }

private:
    std::string_view m_name;  // a literal of k_methods
    std::unique_ptr<Method> m_inner;
};

struct MethodEntry {
    std::string_view name;
    std::unique_ptr<Method> (*make)(const PipelineConfig& config);
};

// In the order method_names() lists them.
constexpr MethodEntry k_methods[] = {
    {"brute", [](const PipelineConfig&) { return make_brute_method(); }},
    {"aabb", [](const PipelineConfig& config) { return make_aabb_method(bvh::aabb_config(config.aabb, config.threads)); }},
    {"gpu", [](const PipelineConfig& config) { return make_gpu_method(config.gpu); }},
    {"gpu-naive", [](const PipelineConfig& config) {
         GpuCullConfig naive = config.gpu;
         naive.naive = true;
         return make_gpu_method(naive);
     }},
    {"aabb-thesis", [](const PipelineConfig& config) -> std::unique_ptr<Method> {  // the thesis's AABB baseline: 5.2.1's 3/4 rule
         AabbOptions thesis = config.aabb;
         thesis.rebuild = AabbRebuildRule::Thesis;
         return std::make_unique<NamedMethod>("aabb-thesis", make_aabb_method(bvh::aabb_config(thesis, config.threads)));
     }},
    {"hybrid", [](const PipelineConfig& config) {
         return make_hybrid_method(std::make_shared<bvh::AabbCuller>(bvh::aabb_config(config.aabb, config.threads)),
                                   config.gpu);
     }},
    {"adaptive", [](const PipelineConfig& config) { return make_adaptive_method(config); }},
    {"adaptive-thesis", [](const PipelineConfig& config) -> std::unique_ptr<Method> {
         PipelineConfig thesis = config;
         thesis.adaptive.policy = AdaptivePolicy::Thesis;
         return std::make_unique<NamedMethod>("adaptive-thesis", make_adaptive_method(thesis));
     }},
    {"adaptive-cost", [](const PipelineConfig& config) -> std::unique_ptr<Method> {
         PipelineConfig cost = config;
         cost.adaptive.policy = AdaptivePolicy::Cost;
         return std::make_unique<NamedMethod>("adaptive-cost", make_adaptive_method(cost));
     }},
};

}  // namespace

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const MethodEntry& entry : k_methods) names.emplace_back(entry.name);
    return names;
}

std::unique_ptr<Method> make_method(std::string_view name, const PipelineConfig& config) {
    for (const MethodEntry& entry : k_methods) {
        if (entry.name == name) return entry.make(config);
    }
    std::string known;
    for (const MethodEntry& entry : k_methods) known += (known.empty() ? "" : ", ") + std::string(entry.name);
    throw std::invalid_argument("unknown method '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace collidescope
