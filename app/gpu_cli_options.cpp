// --gpu-* options -> GpuCullConfig.

#include "gpu_cli_options.hpp"
#include "number_checks.hpp"

#include "named_cli_option.hpp"

#include "collidescope/error.hpp"

namespace collidescope::app {

void add_gpu_options(CLI::App& command, GpuOptions& options) {
    const std::string group = "GPU cull (methods gpu, ...)";
    add_named_option(command, "--gl", options.gl, k_gl_backend_names,
                     "GL context of the GPU cull: auto (a GPU through EGL if any, else OSMesa), osmesa or egl")
        ->group(group);
    add_named_option(command, "--gpu-cull", options.cull, k_gpu_cull_variant_names,
                     "How a pass reads its answers: queries (an occlusion query per P triangles, "
                     "the thesis) or flags (one draw, per-triangle flags in a storage buffer)")
        ->group(group);
    command.add_option("--gpu-resolution", options.resolution, "Width and height of each view's depth buffer")
        ->check(whole_number(1, 8192, "of pixels"))
        ->capture_default_str()
        ->group(group);
    command.add_option("--gpu-views", options.views, "View axes in the order used: one to three of x, y, z")
        ->capture_default_str()
        ->group(group);
    command.add_option("--triangles-per-query", options.triangles_per_query,
                       "P: triangles per occlusion query (thesis 4.2.3); the first P when adaptive")
        ->check(whole_number(1, 1 << 20, "of triangles per query"))
        ->capture_default_str()
        ->group(group);
    command.add_flag("--gpu-fixed-views", options.fixed_views,
                     "Use --gpu-views in order (no view configuration matrix, thesis 4.2.1)")->group(group);
    command.add_flag("--gpu-no-sort", options.no_sort, "Do not sort objects along the view (thesis 4.2.2)")
        ->group(group);
    command.add_flag("--gpu-fixed-p", options.fixed_p,
                     "Keep --triangles-per-query (no adaptive P, thesis 4.2.3)")->group(group);
    command.add_flag("--gpu-no-object-level", options.no_object_level, "Cull triangles only, not objects first")
        ->group(group);
}

GpuCullConfig gpu_config(const GpuOptions& options) {
    GpuCullConfig config;
    config.variant = options.cull;
    config.resolution = options.resolution;
    config.triangles_per_query = options.triangles_per_query;
    config.view_matrix = !options.fixed_views;
    config.sort_objects = !options.no_sort;
    config.adaptive_p = !options.fixed_p;
    config.object_level = !options.no_object_level;
    config.gl = options.gl;
    config.views.clear();
    for (const char axis : options.views) {
        const std::size_t index = std::string_view("xyz").find(axis);
        if (index == std::string_view::npos || options.views.size() > 3) {
            throw InputError("--gpu-views '" + options.views + "': expected one to three of x, y, z");
        }
        config.views.push_back(static_cast<int>(index));
    }
    if (config.views.empty()) throw InputError("--gpu-views is empty: expected one to three of x, y, z");
    return config;
}

}  // namespace collidescope::app
