#pragma once
// The options that choose and tune the engine, shared by the subcommands that run it (check,
// record): --method, --self / --no-self, --threads, the GPU cull's --gpu-* and the AABB
// hierarchies' --aabb-* options, and the sampling of animated model files (--fps, --clip).

#include "aabb_cli_options.hpp"
#include "gpu_cli_options.hpp"

#include "collidescope/pipeline.hpp"
#include "collidescope/scene.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace collidescope::app {

/// What the options hold as parsed.
struct EngineOptions {
    std::string method = "adaptive";
    bool self = false;     ///< force self-collision on
    bool no_self = false;  ///< force self-collision off
    int threads = 0;       ///< 0 = all hardware threads
    GpuOptions gpu;
    AabbOptions aabb;
    AdaptivePolicy policy = AdaptiveOptions{}.policy;  ///< --policy (method adaptive)
    std::uint64_t adaptive_seed = 1;  ///< --adaptive-seed: seeds the exploration draws
    AnimationOptions animation;       ///< --fps, --clip: how animated model files are sampled
};

/// Adds the options to `command`, writing into `options` (which must outlive parsing).
void add_engine_options(CLI::App& command, EngineOptions& options);

/// The pipeline configuration the options describe for `scene` (whose setting decides
/// self-collision unless --self or --no-self says otherwise).
PipelineConfig pipeline_config(const EngineOptions& options, const Scene& scene);

}  // namespace collidescope::app
