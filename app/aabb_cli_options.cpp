// --aabb-* and --rebuild-* options -> AabbOptions.

#include "aabb_cli_options.hpp"

namespace collidescope::app {

void add_aabb_options(CLI::App& command, AabbCliOptions& options) {
    const std::string group = "AABB hierarchies (method aabb)";
    command.add_option("--aabb-builder", options.builder, "Builder of the per-object hierarchies: lbvh or sah")
        ->check(CLI::IsMember({"lbvh", "sah"}))
        ->capture_default_str()
        ->group(group);
    command.add_option("--rebuild-policy", options.rebuild,
                       "When a refit hierarchy is rebuilt: quality (SAH cost past --rebuild-quality-limit), "
                       "thesis (detection time above --rebuild-fraction of a rebuild, thesis 5.2.1) or never; "
                       "topology changes always rebuild")
        ->check(CLI::IsMember({"quality", "thesis", "never"}))
        ->capture_default_str()
        ->group(group);
    command.add_option("--rebuild-quality-limit", options.quality_limit,
                       "Quality rule: rebuild when the SAH cost exceeds this multiple of the post-build cost")
        ->check(CLI::PositiveNumber)
        ->capture_default_str()
        ->group(group);
    command.add_option("--rebuild-fraction", options.thesis_fraction,
                       "Thesis rule: rebuild when detection time exceeds this fraction of a rebuild's time")
        ->check(CLI::PositiveNumber)
        ->capture_default_str()
        ->group(group);
    command.add_option("--background-rebuild", options.background,
                       "Policy rebuilds on a worker thread while frames use the refit tree: on, off, or auto "
                       "(on only when --threads leaves a hardware thread free for the worker)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str()
        ->group(group);
}

AabbOptions aabb_options(const AabbCliOptions& options) {
    AabbOptions result;
    result.builder = options.builder == "sah" ? AabbBuilder::Sah : AabbBuilder::Lbvh;
    result.rebuild = options.rebuild == "thesis" ? AabbRebuildRule::Thesis
                     : options.rebuild == "never" ? AabbRebuildRule::Never
                                                  : AabbRebuildRule::Quality;
    result.quality_limit = options.quality_limit;
    result.thesis_fraction = options.thesis_fraction;
    result.background = options.background == "on"    ? AabbBackground::On
                        : options.background == "off" ? AabbBackground::Off
                                                      : AabbBackground::Auto;
    return result;
}

}  // namespace collidescope::app
