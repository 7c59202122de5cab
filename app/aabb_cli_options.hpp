#pragma once
// The AABB hierarchies' command-line options, for the subcommands that run the engine:
// --aabb-builder, --rebuild-policy, --rebuild-quality-limit, --rebuild-fraction,
// --background-rebuild.

#include "collidescope/aabb_options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace collidescope::app {

/// What the options hold as parsed.
struct AabbCliOptions {
    std::string builder = "lbvh";   ///< lbvh | sah
    std::string rebuild = "quality";  ///< quality | thesis | never
    double quality_limit = AabbOptions{}.quality_limit;
    double thesis_fraction = AabbOptions{}.thesis_fraction;
    std::string background = "auto";  ///< auto | on | off
};

/// Adds the options to `command`, writing into `options` (which must outlive parsing).
void add_aabb_options(CLI::App& command, AabbCliOptions& options);

/// The engine options they describe.
AabbOptions aabb_options(const AabbCliOptions& options);

}  // namespace collidescope::app
