#pragma once
// The GPU cull's command-line options, shared by the subcommands that run the engine
// (check, bench, record): --gl, --gpu-cull, --gpu-resolution, --gpu-views, --triangles-per-query and
// the switches of the thesis's three mechanisms.

#include "collidescope/gpu_cull.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace collidescope::app {

/// What the options hold as parsed.
struct GpuOptions {
    GpuCullVariant cull = GpuCullConfig{}.variant;
    int resolution = GpuCullConfig{}.resolution;
    std::string views = "zxy";     ///< one to three of x, y, z, in order
    std::uint32_t triangles_per_query = GpuCullConfig{}.triangles_per_query;
    bool fixed_views = false;  ///< --gpu-fixed-views: the --gpu-views order, no matrix
    bool no_sort = false;      ///< --gpu-no-sort
    bool fixed_p = false;      ///< --gpu-fixed-p: --triangles-per-query stays
    bool no_object_level = false;
    GlBackend gl = GpuCullConfig{}.gl;
};

/// Adds the options to `command`, writing into `options` (which must outlive parsing).
void add_gpu_options(CLI::App& command, GpuOptions& options);

/// The engine configuration the options describe. Throws InputError on a bad --gpu-views.
GpuCullConfig gpu_config(const GpuOptions& options);

}  // namespace collidescope::app
