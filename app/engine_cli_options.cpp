// --method, --self, --no-self, --threads, --gpu-*, --aabb-* -> PipelineConfig; --fps, --clip.

#include "engine_cli_options.hpp"
#include "number_checks.hpp"

#include "named_cli_option.hpp"
#include "scene_input.hpp"

#include <limits>
#include <stdexcept>

namespace collidescope::app {

void add_engine_options(CLI::App& command, EngineOptions& options) {
    command.add_option("--method", options.method, "Collision method")
        ->check(CLI::IsMember(method_names()))
        ->capture_default_str();
    CLI::Option* self = command.add_flag("--self", options.self, "Self-collision on (default: the scene's setting)");
    command.add_flag("--no-self", options.no_self, "Self-collision off (default: the scene's setting)")->excludes(self);
    command.add_option("--threads", options.threads, "Worker threads (0 = all hardware threads)")
        ->check(whole_number(0, 1024, "of worker threads (0: all hardware threads)"))
        ->capture_default_str();
    add_named_option(command, "--policy", options.policy, k_adaptive_policy_names,
                     "Decision policy of --method adaptive: thesis (Algorithms 4 and 5) or cost (docs/explanation/decision.md)");
    command.add_option("--adaptive-seed", options.adaptive_seed, "Seed of the decision system's exploration draws")
        ->check(whole_number(0, std::numeric_limits<std::int64_t>::max(), "(a seed)"))
        ->capture_default_str();
    command.add_option("--fps", options.animation.fps,
                       "Frames per second at which animated model files are sampled (default 30; docs/reference/animation.md)")
        ->check(positive_number("of frames per second"));
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
    config.aabb = options.aabb;
    config.adaptive.policy = options.policy;
    config.adaptive.seed = options.adaptive_seed;
    return config;
}

}  // namespace collidescope::app
