// --method, --self, --no-self, --threads, --gpu-*, --aabb-* -> PipelineConfig; --fps, --clip.

#include "engine_cli_options.hpp"

#include "scene_input.hpp"

#include <stdexcept>

namespace collidescope::app {

void add_engine_options(CLI::App& command, EngineOptions& options) {
    command.add_option("--method", options.method, "Collision method")
        ->check(CLI::IsMember(method_names()))
        ->capture_default_str();
    CLI::Option* self = command.add_flag("--self", options.self, "Self-collision on (default: the scene's setting)");
    command.add_flag("--no-self", options.no_self, "Self-collision off (default: the scene's setting)")->excludes(self);
    command.add_option("--threads", options.threads, "Worker threads (0 = all hardware threads)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command.add_option("--policy", options.policy,
                       "Decision policy of --method adaptive: thesis (Algorithms 4 and 5) or cost (docs/decision.md)")
        ->check(CLI::IsMember({"thesis", "cost"}))
        ->capture_default_str();
    command.add_option("--adaptive-seed", options.adaptive_seed, "Seed of the decision system's exploration draws")
        ->capture_default_str();
    command.add_option("--fps", options.animation.fps,
                       "Frames per second at which animated model files are sampled (default 30; docs/animation.md)")
        ->check(CLI::PositiveNumber);
    command.add_option("--clip", options.animation.clip,
                       "Animation clip of animated model files: a name or an index from 0 (default the first)");
    add_gpu_options(command, options.gpu);
    add_aabb_options(command, options.aabb);
}

PipelineConfig pipeline_config(const EngineOptions& options, const Scene& scene) {
    PipelineConfig config;
    config.method = options.method;
    config.self_collision = resolve_self_collision(options.self, options.no_self, scene);
    config.threads = options.threads;
    config.gpu = gpu_config(options.gpu);
    config.aabb = aabb_options(options.aabb);
    config.adaptive.policy = parse_policy(options.policy);
    config.adaptive.seed = options.adaptive_seed;
    return config;
}

AdaptivePolicy parse_policy(const std::string& name) {
    if (name == "thesis") return AdaptivePolicy::Thesis;
    if (name == "cost") return AdaptivePolicy::Cost;
    throw std::invalid_argument("unknown policy '" + name + "' (known: thesis, cost)");
}

}  // namespace collidescope::app
