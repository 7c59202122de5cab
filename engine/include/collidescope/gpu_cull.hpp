#pragma once
/// Options and per-frame trace of Mode 2, the GPU image-space cull (engine/src/gpucull;
/// thesis 3.2, 4.2; docs/explanation/gpu_cull.md).

#include "collidescope/gl_backend.hpp"
#include "collidescope/option_names.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace collidescope {

/// How a cull pass learns which items are not fully visible.
enum class GpuCullVariant {
    Queries,  ///< one occlusion query per item or batch of triangles (CULLIDE, the thesis)
    Flags,    ///< one draw per object; the fragment shader sets per-triangle flags (query-free)
};

/// The names of GpuCullVariant (--gpu-cull).
inline constexpr OptionNames<GpuCullVariant, 2> k_gpu_cull_variant_names{
    {{"queries", GpuCullVariant::Queries}, {"flags", GpuCullVariant::Flags}}};

/// Options of the GPU cull. The thesis's three mechanisms (4.2) are each switchable.
struct GpuCullConfig {
    /// Width and height of each view's depth buffer, pixels. 256 under llvmpipe: on C:small,
    /// 512 halves the PCS left again but costs 1.7x the time (docs/explanation/gpu_cull.md).
    int resolution = 256;
    /// View axes in the order used (0 = x, 1 = y, 2 = z); with `view_matrix` only their number
    /// counts (the matrix picks the axes).
    std::vector<int> views = {2, 0, 1};
    /// P: triangles per occlusion query (Queries only); the first P when `adaptive_p` is on.
    std::uint32_t triangles_per_query = 16;
    GpuCullVariant variant = GpuCullVariant::Queries;
    bool object_level = true;             ///< cull whole objects before their triangles
    bool view_matrix = true;              ///< 4.2.1, Algorithm 2: views from the scored matrix
    double view_decay_rate = 0.9;         ///< DECAY_RATE of Equation 4.2
    bool sort_objects = true;             ///< 4.2.2: draw objects front to back along the view
    bool adaptive_p = true;               ///< 4.2.3, Algorithm 3: P moves with the cost model
    std::uint32_t max_triangles_per_query = 64;  ///< upper limit of the adaptive P
    /// The thesis's naive baseline (method gpu-naive): a random order of the views each frame
    /// (seeded), one triangle per query, no sort; the other mechanism switches are ignored.
    bool naive = false;
    std::uint64_t seed = 1;               ///< seeds the exploration and naive draws
    /// Capture the depth buffers (GpuFrameInfo::depth_images) on frames whose index is a
    /// multiple of this; 0: never (the default; a capture costs a read back per view).
    std::uint32_t depth_every = 0;
    /// The GL context's implementation (`--gl`): auto picks a GPU through EGL when there is
    /// one, else OSMesa.
    GlBackend gl = GlBackend::Auto;
};

/// One depth buffer of the cull, read back after the forward pass of a view at the triangle
/// level: the nearest depth of every PCS triangle drawn in that view.
struct GpuDepthImage {
    std::uint8_t level = 1;  ///< 0 objects, 1 triangles
    std::uint8_t view = 0;   ///< view axis (0 = x, 1 = y, 2 = z)
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    /// Window depth in [0, 1] per pixel, row-major, bottom row first (GL order); 1 where
    /// nothing was drawn.
    std::vector<float> depth;
    /// The world coordinates along the view axis that window depth 0 and 1 map to.
    double depth_near = 0;
    double depth_far = 1;
};

/// One cull pass: a level (objects or triangles), a view, a direction.
struct GpuPassInfo {
    std::uint8_t level = 0;         ///< 0 objects, 1 triangles
    std::uint8_t view = 0;          ///< view axis (0 = x, 1 = y, 2 = z)
    std::uint8_t reverse = 0;       ///< 0 forward pass, 1 reverse pass
    std::uint32_t items_tested = 0; ///< objects or triangles tested (the first drawn needs no test)
    std::uint32_t items_hidden = 0; ///< of those, not fully visible (some sample at or behind)
    std::uint32_t queries = 0;      ///< occlusion queries issued (0 with flags)
    std::uint64_t samples_passed = 0;  ///< samples counted by those queries
    std::uint32_t triangles_per_query = 0;  ///< P used (0 with flags)
};

/// One view of one level: the PCS before and after its two passes.
struct GpuViewInfo {
    std::uint8_t level = 0;
    std::uint8_t view = 0;
    std::uint32_t pcs_in = 0;   ///< objects or triangles in the PCS before the view
    std::uint32_t pcs_out = 0;  ///< after it
};

/// What the GPU cull did in one frame.
struct GpuFrameInfo {
    std::vector<GpuPassInfo> passes;
    std::vector<GpuViewInfo> views;
    std::uint32_t pcs_objects_in = 0;     ///< objects in inter-object pairs
    std::uint32_t pcs_objects_out = 0;    ///< objects left with triangles in the PCS
    std::uint32_t pcs_triangles_in = 0;   ///< their triangles
    std::uint32_t pcs_triangles_out = 0;  ///< triangles that survived the cull
    std::uint64_t queries = 0;            ///< occlusion queries issued in the frame
    std::string renderer;                 ///< GL_RENDERER of the context that culled
    /// The view configuration matrix after this frame (row = cull pass, column = x, y, z);
    /// zero when the matrix is off.
    std::array<std::array<double, 3>, 3> view_matrix{};
    std::vector<std::uint8_t> chosen_views;  ///< the axes this frame's passes used, in order
    std::uint32_t triangles_per_query = 0;   ///< P this frame used (0 with flags)
    double query_ms = 0;                  ///< O: measured milliseconds per occlusion query
    double rebuild_ms_per_triangle = 0;   ///< R: final-step milliseconds per surviving triangle
    /// (object, triangle) of every triangle left in the PCS after the cull, ascending.
    std::vector<std::array<std::uint32_t, 2>> survivors;
    /// Depth buffers, when GpuCullConfig::depth_every asked for them this frame.
    std::vector<GpuDepthImage> depth_images;
};

/// Calls `visit(name, value, unit)` for every per-frame scalar of the GPU cull's trace, in a
/// fixed order (the recorder stores one dataset per name; docs/reference/recording.md lists them).
template <class Visitor>
void for_each_gpu_value(const GpuFrameInfo& info, Visitor&& visit) {
    visit("pcs_objects_in", double(info.pcs_objects_in), "1");
    visit("pcs_objects_out", double(info.pcs_objects_out), "1");
    visit("pcs_triangles_in", double(info.pcs_triangles_in), "1");
    visit("pcs_triangles_out", double(info.pcs_triangles_out), "1");
    visit("queries", double(info.queries), "1");
    visit("triangles_per_query", double(info.triangles_per_query), "1");
    visit("query_ms", info.query_ms, "ms");
    visit("rebuild_ms_per_triangle", info.rebuild_ms_per_triangle, "ms");
    static constexpr const char* k_matrix[3][3] = {{"view_matrix_0x", "view_matrix_0y", "view_matrix_0z"},
                                                   {"view_matrix_1x", "view_matrix_1y", "view_matrix_1z"},
                                                   {"view_matrix_2x", "view_matrix_2y", "view_matrix_2z"}};
    for (std::size_t pass = 0; pass < 3; ++pass) {
        for (std::size_t view = 0; view < 3; ++view) visit(k_matrix[pass][view], info.view_matrix[pass][view], "1");
    }
    static constexpr const char* k_chosen[3] = {"chosen_view_0", "chosen_view_1", "chosen_view_2"};
    for (std::size_t pass = 0; pass < 3; ++pass) {  // axis 0/1/2, -1 when the pass did not run
        visit(k_chosen[pass], pass < info.chosen_views.size() ? double(info.chosen_views[pass]) : -1.0, "1");
    }
}

/// Calls `visit(name, value)` for every field of one cull pass, in a fixed order (the recorder
/// stores passes as rows of this many columns).
template <class Visitor>
void for_each_pass_field(const GpuPassInfo& pass, Visitor&& visit) {
    visit("level", std::uint64_t{pass.level});
    visit("view", std::uint64_t{pass.view});
    visit("reverse", std::uint64_t{pass.reverse});
    visit("items_tested", std::uint64_t{pass.items_tested});
    visit("items_hidden", std::uint64_t{pass.items_hidden});
    visit("queries", std::uint64_t{pass.queries});
    visit("samples_passed", pass.samples_passed);
    visit("triangles_per_query", std::uint64_t{pass.triangles_per_query});
}

}  // namespace collidescope
