#pragma once
// The AABB hierarchies' command-line options, for the subcommands that run the engine:
// --aabb-builder, --rebuild-policy, --rebuild-quality-limit, --rebuild-fraction,
// --background-rebuild.

#include "collidescope/aabb_options.hpp"

#include <CLI/CLI.hpp>

namespace collidescope::app {

/// Adds the options to `command`, writing into `options` (which must outlive parsing; its
/// values are the defaults shown).
void add_aabb_options(CLI::App& command, AabbOptions& options);

}  // namespace collidescope::app
