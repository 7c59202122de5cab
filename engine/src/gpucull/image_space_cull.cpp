// The CULLIDE passes over the PCS: per level (objects, then triangles) and view, a forward and
// a reverse pass; items fully visible in both leave the PCS.

#include "gpucull/image_space_cull.hpp"

#include "stats/stopwatch.hpp"

#include <algorithm>
#include <limits>

namespace collidescope::gpucull {
namespace {

enum Level : std::uint8_t { Objects = 0, Triangles = 1 };

// Every PCS triangle of one view as a quad, object after object in drawing order.
struct ViewSet {
    View view;
    std::vector<TriangleQuad> quads;
    std::vector<std::size_t> entry;    ///< per drawn object, its index in the PCS
    std::vector<std::uint32_t> first;  ///< per drawn object, its first quad; first.back() = total
};

Eigen::AlignedBox3d pcs_bounds(const Frame& frame, const std::vector<PcsObject>& pcs) {
    Eigen::AlignedBox3d bounds;
    for (const PcsObject& entry : pcs) {
        const ObjectFrame& object = frame.objects[entry.object];
        for (const std::uint32_t tri : entry.triangles) {
            for (const std::uint32_t v : object.topology->triangles[tri]) bounds.extend(object.vertices[v]);
        }
    }
    return bounds;
}

// The drawing order: PCS order, or sorted front to back along the view axis (thesis 4.2.2:
// by each object's nearest PCS corner; ties keep PCS order).
std::vector<std::size_t> drawing_order(const Frame& frame, const std::vector<PcsObject>& pcs, int axis, bool sort) {
    std::vector<std::size_t> order(pcs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    if (!sort) return order;
    std::vector<double> nearest(pcs.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < pcs.size(); ++i) {
        const ObjectFrame& object = frame.objects[pcs[i].object];
        for (const std::uint32_t tri : pcs[i].triangles) {
            for (const std::uint32_t v : object.topology->triangles[tri]) nearest[i] = std::min(nearest[i], object.vertices[v][axis]);
        }
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nearest[a] < nearest[b]; });
    return order;
}

ViewSet make_view_set(const Frame& frame, const std::vector<PcsObject>& pcs, int axis, const CullPlan& plan) {
    ViewSet set{View{axis, pcs_bounds(frame, pcs), plan.resolution, plan.resolution}, {}, {}, {0}};
    set.entry = drawing_order(frame, pcs, axis, plan.sort_objects);
    for (const std::size_t index : set.entry) {
        const PcsObject& entry = pcs[index];
        const ObjectFrame& object = frame.objects[entry.object];
        for (const std::uint32_t tri : entry.triangles) {
            const std::array<Vec3, 3> p = object.corners(tri);
            set.quads.push_back(make_quad(set.view, p[0], p[1], p[2], static_cast<std::uint32_t>(set.quads.size())));
        }
        set.first.push_back(static_cast<std::uint32_t>(set.quads.size()));
    }
    return set;
}

// Issues one pass: each object (in pass order) is tested against the depth of the objects
// drawn before it, then drawn. The first object meets an empty buffer and needs no test; the
// last one is tested by no object after it, so it is drawn only when the depth buffer is read
// back for the trace (`keep_depth`): a third of the pass's rasterisation with two objects.
void issue_pass(const ViewSet& set, Level level, bool reverse, bool keep_depth, const CullPlan& plan,
                CullRenderer& renderer, GpuPassInfo& pass) {
    const std::size_t n = set.first.size() - 1;
    renderer.clear_depth();
    if (level == Triangles && plan.variant == GpuCullVariant::Flags) renderer.clear_flags(set.first.back());
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = reverse ? n - 1 - i : i;
        const std::uint32_t first = set.first[k];
        const std::uint32_t count = set.first[k + 1] - first;
        if (i > 0) {
            if (level == Objects) {
                renderer.test_with_queries(first, count, count);
            } else if (plan.variant == GpuCullVariant::Flags) {
                renderer.test_with_flags(first, count);
            } else {
                renderer.test_with_queries(first, count, plan.triangles_per_query);
            }
            pass.items_tested += level == Objects ? 1 : count;
        }
        if (i + 1 < n || keep_depth) renderer.draw_occluders(first, count);
    }
}

// Reads the pass's answers back into `hidden` (per quad: not fully visible), in issue order.
void read_pass(const ViewSet& set, Level level, bool reverse, const CullPlan& plan,
               CullRenderer& renderer, GpuPassInfo& pass, std::vector<std::uint8_t>& hidden) {
    const std::size_t n = set.first.size() - 1;
    const bool flags = level == Triangles && plan.variant == GpuCullVariant::Flags;
    const std::vector<std::uint32_t> answers = flags ? renderer.read_flags(set.first.back()) : renderer.read_queries();
    std::size_t query = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const std::size_t k = reverse ? n - 1 - i : i;
        const std::uint32_t first = set.first[k];
        const std::uint32_t count = set.first[k + 1] - first;
        const std::uint32_t batch = level == Objects ? count : (flags ? 1 : std::max<std::uint32_t>(1, plan.triangles_per_query));
        for (std::uint32_t at = 0; at < count; at += batch) {
            const std::uint32_t size = std::min(batch, count - at);
            const std::uint32_t answer = flags ? answers[first + at] : answers[query++];
            if (!flags) pass.samples_passed += answer;
            if (answer == 0) continue;
            std::fill_n(hidden.begin() + first + at, size, std::uint8_t{1});
            pass.items_hidden += level == Objects ? 1 : size;
        }
    }
    pass.queries = static_cast<std::uint32_t>(query);
    pass.triangles_per_query = flags ? 0 : (level == Objects ? 0 : plan.triangles_per_query);
}

// The depth buffer as the trace records it. Window depth d maps to the view-axis coordinate
// lo + (d - 0.25) / s, s the view's depth scale (project() in view_quads.cpp: [lo, hi] to
// [0.25, 0.75]; s = 1 for a flat PCS), so d = 0 and d = 1 are lo - 0.25 / s and lo + 0.75 / s.
GpuDepthImage capture_depth(const View& view, CullRenderer& renderer) {
    GpuDepthImage image;
    image.level = Triangles;
    image.view = static_cast<std::uint8_t>(view.axis);
    image.width = static_cast<std::uint32_t>(view.width);
    image.height = static_cast<std::uint32_t>(view.height);
    image.depth = renderer.read_depth();
    const double lo = view.bounds.min()[view.axis];
    const double extent = view.bounds.max()[view.axis] - lo;
    const double scale = extent > 0 ? 0.5 / extent : 1.0;
    image.depth_near = lo - 0.25 / scale;
    image.depth_far = lo + 0.75 / scale;
    return image;
}

std::uint32_t pcs_size(const std::vector<PcsObject>& pcs, Level level) {
    if (level == Objects) return static_cast<std::uint32_t>(pcs.size());
    std::uint32_t size = 0;
    for (const PcsObject& entry : pcs) size += static_cast<std::uint32_t>(entry.triangles.size());
    return size;
}

// Keeps the items hidden in at least one pass; drops objects left empty, and everything when
// fewer than two objects remain (nothing left to collide with).
void shrink(std::vector<PcsObject>& pcs, const ViewSet& set, Level level,
            const std::vector<std::uint8_t>& hidden_forward, const std::vector<std::uint8_t>& hidden_reverse) {
    for (std::size_t slot = 0; slot < set.entry.size(); ++slot) {
        PcsObject& entry = pcs[set.entry[slot]];
        const std::uint32_t first = set.first[slot];
        std::vector<std::uint32_t> kept;
        for (std::uint32_t i = 0; i < entry.triangles.size(); ++i) {
            const bool keep = level == Objects ? (hidden_forward[first] || hidden_reverse[first])
                                               : (hidden_forward[first + i] || hidden_reverse[first + i]);
            if (keep) kept.push_back(entry.triangles[i]);
        }
        entry.triangles = std::move(kept);
    }
    std::erase_if(pcs, [](const PcsObject& entry) { return entry.triangles.empty(); });
    if (pcs.size() < 2) pcs.clear();
}

void cull_view(const Frame& frame, std::vector<PcsObject>& pcs, Level level, int axis, const CullPlan& plan,
               CullRenderer& renderer, GpuFrameInfo& info, CullTimes& times) {
    GpuViewInfo view_info{level, static_cast<std::uint8_t>(axis), pcs_size(pcs, level), 0};
    Stopwatch stopwatch;
    const ViewSet set = make_view_set(frame, pcs, axis, plan);
    renderer.begin_view(set.quads, set.view.width, set.view.height);
    std::vector<std::uint8_t> hidden[2];
    for (const bool reverse : {false, true}) {
        GpuPassInfo pass{level, static_cast<std::uint8_t>(axis), static_cast<std::uint8_t>(reverse)};
        const bool keep_depth = level == Triangles && !reverse && plan.capture_depth;
        issue_pass(set, level, reverse, keep_depth, plan, renderer, pass);
        times.render += stopwatch.lap_ms();
        hidden[reverse].assign(set.quads.size(), 0);
        read_pass(set, level, reverse, plan, renderer, pass, hidden[reverse]);
        // Testers leave the depth buffer as the occluders wrote it: every PCS triangle drawn.
        if (keep_depth) info.depth_images.push_back(capture_depth(set.view, renderer));
        times.readback += stopwatch.lap_ms();
        info.queries += pass.queries;
        info.passes.push_back(pass);
    }
    shrink(pcs, set, level, hidden[0], hidden[1]);
    view_info.pcs_out = pcs_size(pcs, level);
    info.views.push_back(view_info);
}

}  // namespace

void cull_pcs(const Frame& frame, std::vector<PcsObject>& pcs, const CullPlan& plan,
              CullRenderer& renderer, GpuFrameInfo& info, CullTimes& times) {
    info.pcs_objects_in = static_cast<std::uint32_t>(pcs.size());
    info.pcs_triangles_in = pcs_size(pcs, Triangles);
    if (pcs.size() < 2) pcs.clear();
    for (const Level level : {Objects, Triangles}) {
        if (level == Objects && !plan.object_level) continue;
        for (const int axis : plan.views) {
            if (pcs.empty()) break;
            cull_view(frame, pcs, level, axis, plan, renderer, info, times);
        }
    }
    info.pcs_objects_out = static_cast<std::uint32_t>(pcs.size());
    info.pcs_triangles_out = pcs_size(pcs, Triangles);
}

}  // namespace collidescope::gpucull
