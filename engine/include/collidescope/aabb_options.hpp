#pragma once
/// Options of the `aabb` method (Mode 1, engine/src/bvh), as the command line and
/// PipelineConfig carry them. Defaults are the method's defaults.

#include "collidescope/option_names.hpp"

#include <cstdint>

namespace collidescope {

/// Which builder (re)builds the per-object hierarchies.
enum class AabbBuilder : std::uint8_t {
    Lbvh,  ///< linear (Morton) build: the default, fastest as a rebuild (bench_bvh_datasets)
    Sah,   ///< top-down binned SAH: slower build, cheaper trees
};

/// When a refit hierarchy is rebuilt (a topology change always rebuilds).
enum class AabbRebuildRule : std::uint8_t {
    Quality,  ///< SAH cost above quality_limit times the cost right after the last build
    Thesis,   ///< thesis 5.2.1: last frame's detection time above thesis_fraction of a rebuild
    Never,    ///< refit only
};

/// Where the rebuild policy's rebuilds run (a topology change or a missing tree is always built
/// inside the frame).
enum class AabbBackground : std::uint8_t {
    /// On a worker only when the frames' worker threads leave a hardware thread free for it
    /// (--threads below the machine's); else inside the frame. On 2 cores with both busy, a
    /// frame traversing while the worker builds took 2-3x its time (docs/explanation/decision.md).
    Auto,
    On,   ///< on a worker thread while frames use the refit tree (thesis contribution 3)
    Off,  ///< inside the frame, on the engine thread and its workers
};

/// The names of AabbBuilder, AabbRebuildRule and AabbBackground (--aabb-builder,
/// --rebuild-policy, --background-rebuild).
inline constexpr OptionNames<AabbBuilder, 2> k_aabb_builder_names{
    {{"lbvh", AabbBuilder::Lbvh}, {"sah", AabbBuilder::Sah}}};
inline constexpr OptionNames<AabbRebuildRule, 3> k_aabb_rebuild_rule_names{
    {{"quality", AabbRebuildRule::Quality}, {"thesis", AabbRebuildRule::Thesis}, {"never", AabbRebuildRule::Never}}};
inline constexpr OptionNames<AabbBackground, 3> k_aabb_background_names{
    {{"auto", AabbBackground::Auto}, {"on", AabbBackground::On}, {"off", AabbBackground::Off}}};

struct AabbOptions {
    AabbBuilder builder = AabbBuilder::Lbvh;
    AabbRebuildRule rebuild = AabbRebuildRule::Quality;
    double quality_limit = 1.5;     ///< quality rule threshold (relative SAH cost)
    /// Quality rule: a rebuild must pay for itself within this many frames (an upper bound on
    /// the detection time it saves, against its build time); 0: the SAH cost alone decides.
    double payback_frames = 16;
    double thesis_fraction = 0.75;  ///< thesis rule: "three fourths of a rebuild"
    AabbBackground background = AabbBackground::Auto;
};

}  // namespace collidescope
