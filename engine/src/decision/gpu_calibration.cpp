// Two wavy sheets that cross each other along many lines, at two sizes, through the GPU cull.

#include "decision/gpu_calibration.hpp"

#include "stages/narrow_phase.hpp"
#include "stages/object_level.hpp"
#include "stats/stopwatch.hpp"
#include "gpucull/gpu_culler.hpp"
#include "scene/file_source.hpp"

#include <algorithm>
#include <cmath>

namespace collidescope::decision {
namespace {

// An n x n grid of quads (2 n^2 triangles) over [0, 1]^2 at height phase-shifted waves.
ObjectFrame wavy_sheet(std::uint32_t n, double sign, std::uint64_t revision) {
    auto topology = std::make_shared<Topology>();
    std::vector<Vec3> vertices;
    for (std::uint32_t y = 0; y <= n; ++y) {
        for (std::uint32_t x = 0; x <= n; ++x) {
            const double u = double(x) / n, v = double(y) / n;
            vertices.emplace_back(u, v, sign * 0.05 * std::sin(12.0 * u) * std::cos(9.0 * v));
        }
    }
    for (std::uint32_t y = 0; y < n; ++y) {
        for (std::uint32_t x = 0; x < n; ++x) {
            const std::uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            topology->triangles.push_back({a, b, d});
            topology->triangles.push_back({a, d, c});
        }
    }
    topology->vertex_count = static_cast<std::uint32_t>(vertices.size());
    topology->revision = revision;
    return {std::move(topology), std::move(vertices)};
}

// Milliseconds of one frame of the `gpu` method (the cull, then the exact test) on two n x n
// sheets.
double time_frame(gpucull::GpuCuller& culler, std::uint32_t n, std::uint32_t index) {
    Frame frame;
    frame.index = index;
    frame.objects.push_back(wavy_sheet(n, 1.0, next_topology_revision()));
    frame.objects.push_back(wavy_sheet(n, -1.0, next_topology_revision()));
    const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
    const std::vector<ObjectPair> pairs = find_object_pairs(boxes, false);
    const FrameContext context{frame, boxes, pairs, false};
    std::vector<TrianglePair> found;
    FrameStats stats;
    Stopwatch stopwatch;
    const std::vector<TrianglePair> candidates = culler.cull(context, stats);
    narrow_phase(frame, candidates, found, stats);
    return stopwatch.elapsed_ms();
}

}  // namespace

GpuCostPrior measure_gpu_prior(const GpuCullConfig& config) {
    gpucull::GpuCuller culler(config);
    constexpr std::uint32_t k_small = 16, k_large = 48;  // 1,024 and 9,216 triangles in all
    std::uint32_t index = 0;
    const auto frame_ms = [&](std::uint32_t n) { return time_frame(culler, n, index++); };
    frame_ms(k_small);  // warm up: shaders, buffers
    const double small = frame_ms(k_small);
    frame_ms(k_large);  // warm up: the larger buffers
    const double large = frame_ms(k_large);
    const double t_small = 2.0 * k_small * k_small * 2, t_large = 2.0 * k_large * k_large * 2;
    GpuCostPrior prior;
    prior.per_triangle_ms = std::max(0.0, (large - small) / (t_large - t_small));
    prior.fixed_ms = std::max(0.0, small - prior.per_triangle_ms * t_small);
    return prior;
}

}  // namespace collidescope::decision
