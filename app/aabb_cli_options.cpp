// --aabb-* and --rebuild-* options -> AabbOptions.

#include "aabb_cli_options.hpp"
#include "number_checks.hpp"

#include "named_cli_option.hpp"

namespace collidescope::app {

void add_aabb_options(CLI::App& command, AabbOptions& options) {
    const std::string group = "AABB hierarchies (method aabb)";
    add_named_option(command, "--aabb-builder", options.builder, k_aabb_builder_names,
                     "Builder of the per-object hierarchies: " + option_name_list(k_aabb_builder_names))
        ->group(group);
    add_named_option(command, "--rebuild-policy", options.rebuild, k_aabb_rebuild_rule_names,
                     "When a refit hierarchy is rebuilt: quality (SAH cost past --rebuild-quality-limit), "
                     "thesis (detection time above --rebuild-fraction of a rebuild, thesis 5.2.1) or never; "
                     "topology changes always rebuild")
        ->group(group);
    command.add_option("--rebuild-quality-limit", options.quality_limit,
                       "Quality rule: rebuild when the SAH cost exceeds this multiple of the post-build cost")
        ->check(positive_number("(a multiple of the SAH cost right after a build)"))
        ->capture_default_str()
        ->group(group);
    command.add_option("--rebuild-payback-frames", options.payback_frames,
                       "Quality rule: rebuild only when the detection time it can save pays for the build "
                       "within this many frames (0: the SAH cost alone decides)")
        ->check(non_negative_number("of frames (0: the SAH cost alone decides)"))
        ->capture_default_str()
        ->group(group);
    command.add_option("--rebuild-fraction", options.thesis_fraction,
                       "Thesis rule: rebuild when detection time exceeds this fraction of a rebuild's time")
        ->check(positive_number("(a fraction of a rebuild's time)"))
        ->capture_default_str()
        ->group(group);
    add_named_option(command, "--background-rebuild", options.background, k_aabb_background_names,
                     "Policy rebuilds on a worker thread while frames use the refit tree: on, off, or auto "
                     "(on only when --threads leaves a hardware thread free for the worker)")
        ->group(group);
}

}  // namespace collidescope::app
