// Build speed of the two builders (binned SAH, LBVH), in million triangles per second, with
// the tree's SAH cost and depth (quality: lower cost = faster traversal).
//
//   build-bvh/bench/bench_bvh_build [--benchmark_repetitions=5]
//
// Meshes: a 1M-triangle grid sheet, a 1M-triangle soup (random small triangles in a cube),
// the E4 dragon (default preset, 47,794 triangles). Which builder wins as the rebuild of a
// deforming mesh (build cost plus the traversal it buys) is measured per data set by
// bench_bvh_datasets (variants every_frame_sah / every_frame_lbvh).

#include "bvh/bvh.hpp"

#include "collidescope/datasets.hpp"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <random>

namespace {

using namespace collidescope;

struct Mesh {
    std::vector<TriIndices> triangles;
    std::vector<Vec3> vertices;
};

Mesh sheet_mesh(std::uint32_t cells) {
    Mesh mesh;
    const std::uint32_t side = cells + 1;
    for (std::uint32_t y = 0; y < side; ++y) {
        for (std::uint32_t x = 0; x < side; ++x) mesh.vertices.emplace_back(x, y, 0.1 * ((x * 7 + y * 3) % 5));
    }
    for (std::uint32_t y = 0; y < cells; ++y) {
        for (std::uint32_t x = 0; x < cells; ++x) {
            const std::uint32_t v = y * side + x;
            mesh.triangles.push_back({v, v + 1, v + side});
            mesh.triangles.push_back({v + 1, v + side + 1, v + side});
        }
    }
    return mesh;
}

Mesh soup_mesh(std::uint32_t count) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> where(0.0, 100.0);
    std::uniform_real_distribution<double> offset(-0.5, 0.5);
    Mesh mesh;
    for (std::uint32_t t = 0; t < count; ++t) {
        const Vec3 c(where(rng), where(rng), where(rng));
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int k = 0; k < 3; ++k) mesh.vertices.push_back(c + Vec3(offset(rng), offset(rng), offset(rng)));
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    return mesh;
}

const Mesh& mesh_by_index(std::int64_t index) {
    static const Mesh sheet = sheet_mesh(708);
    static const Mesh soup = soup_mesh(1'000'000);
    static const Mesh dragon = [] {
        const Frame frame = make_builtin_scene("E4").source->frame(0);
        return Mesh{frame.objects[0].topology->triangles, frame.objects[0].vertices.to_vector()};
    }();
    return index == 0 ? sheet : index == 1 ? soup : dragon;
}

void BM_build(benchmark::State& state) {
    const Mesh& mesh = mesh_by_index(state.range(1));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(2)));
    bvh::BuildConfig config;
    config.builder = state.range(0) == 0 ? bvh::Builder::Sah : bvh::Builder::Lbvh;
    bvh::Tree tree;
    bvh::BuildStats stats;
    for (auto _ : state) {
        stats = bvh::build_tree(mesh.triangles, mesh.vertices, config, tree);
        benchmark::DoNotOptimize(tree.nodes.data());
    }
    state.counters["Mtris_per_s"] = benchmark::Counter(static_cast<double>(mesh.triangles.size()) * 1e-6,
                                                       benchmark::Counter::kIsIterationInvariantRate);
    state.counters["sah_cost"] = stats.sah_cost;
    state.counters["depth"] = stats.depth;
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

// Arguments: builder (0 SAH, 1 LBVH), mesh (0 sheet 1M, 1 soup 1M, 2 dragon 48k), threads.
BENCHMARK(BM_build)
    ->ArgNames({"builder", "mesh", "threads"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}, {1, 2}})
    ->UseRealTime()  // rates per wall-clock second (CPU time counts the main thread only)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
