// Refit against a streaming floor measured in the same run: the floor is one parallel pass
// that reads every vertex position once and writes every node box once (what any refit must
// at least move through memory); refit additionally gathers three vertices per triangle
// through the index buffer. Issue 4's target: refit within 2x of the floor.
//
//   build-bvh/bench/bench_bvh_refit [--benchmark_repetitions=5]
//
// Counters: refit_ns_per_tri, floor_ns_per_tri, ratio (refit / floor), nodes, and the
// refit tree's quality (SAH cost relative to the build) on the deformed positions; and two
// gather floors (the corner gathers alone, in leaf order and in the input's triangle order)
// with refit_per_leaf_gather (refit / the leaf-order gather floor).
// Meshes: a 1M-triangle grid sheet (a deforming cloth: connectivity kept, vertices waved)
// and the E4 data set's dragon (default preset, 47,794 triangles), vertices jittered.

#include "bvh/bvh.hpp"

#include "collidescope/datasets.hpp"

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>

namespace {

using namespace collidescope;
using Clock = std::chrono::steady_clock;

struct Mesh {
    std::vector<TriIndices> triangles;
    std::vector<Vec3> rest;
    std::vector<std::vector<Vec3>> frames;  ///< deformed positions, cycled through
};

Mesh sheet_mesh(std::uint32_t cells) {
    Mesh mesh;
    const std::uint32_t side = cells + 1;
    for (std::uint32_t y = 0; y < side; ++y) {
        for (std::uint32_t x = 0; x < side; ++x) mesh.rest.emplace_back(x, y, 0.0);
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

Mesh dragon_mesh() {
    const Frame frame = make_builtin_scene("E4").source->frame(0);
    Mesh mesh;
    mesh.triangles = frame.objects[0].topology->triangles;
    mesh.rest = frame.objects[0].vertices.to_vector();
    return mesh;
}

// Four deformed copies: a travelling wave of a few cells' amplitude.
void deform(Mesh& mesh, double amplitude) {
    for (int f = 0; f < 4; ++f) {
        std::vector<Vec3> moved = mesh.rest;
        for (Vec3& v : moved) v.z() += amplitude * std::sin(0.05 * v.x() + 0.7 * f) * std::cos(0.03 * v.y());
        mesh.frames.push_back(std::move(moved));
    }
}

// The floor: reads each vertex once and writes each node box once, in parallel chunks.
void stream_floor(std::span<const Vec3> vertices, std::vector<bvh::Node>& nodes) {
    const std::size_t total = std::max(vertices.size(), nodes.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 8192), [&](const tbb::blocked_range<std::size_t>& r) {
        bvh::Aabb box;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            if (i < vertices.size()) box.grow(vertices[i]);
            if (i < nodes.size()) nodes[i].box = box;
        }
    });
}

// Gather floors, diagnostic: the corner gathers any refit over these triangles must make, and
// nothing else. Each reads every triangle's three vertices through its index triple, in the
// order given (the tree's leaf order, or the input's triangle order), and keeps one running
// box per parallel chunk, stored at the chunk's first slot of `sink` (one slot per triangle,
// so chunks never share one), so the loads cannot be dropped. Refit / gather floor says what
// refit costs beyond its gathers; gather floor / streaming floor what the gathers cost beyond
// reading each vertex once in order.
void gather_floor(std::span<const TriIndices> triangles, std::span<const Vec3> vertices, std::vector<bvh::Aabb>& sink) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 8192), [&](const tbb::blocked_range<std::size_t>& r) {
        bvh::Aabb box;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            for (const std::uint32_t v : triangles[i]) box.grow(vertices[v]);
        }
        sink[r.begin()] = box;
    });
}

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void run_refit(benchmark::State& state, Mesh& mesh) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(0)));
    bvh::Tree tree;
    bvh::build_tree(mesh.triangles, mesh.rest, bvh::BuildConfig{}, tree);
    std::vector<bvh::Node> floor_nodes(tree.nodes.size());
    std::vector<bvh::Aabb> gather_sink(mesh.triangles.size());
    double refit_ms = 0;
    double floor_ms = 0;
    double leaf_gather_ms = 0;
    double input_gather_ms = 0;
    double quality = 0;
    std::size_t k = 0;
    for (auto _ : state) {
        const std::vector<Vec3>& vertices = mesh.frames[k++ % mesh.frames.size()];
        Clock::time_point start = Clock::now();
        stream_floor(vertices, floor_nodes);
        floor_ms += ms_since(start);
        start = Clock::now();
        gather_floor(tree.leaf_triangles, vertices, gather_sink);
        leaf_gather_ms += ms_since(start);
        start = Clock::now();
        gather_floor(mesh.triangles, vertices, gather_sink);
        input_gather_ms += ms_since(start);
        start = Clock::now();
        quality = bvh::refit(tree, mesh.triangles, vertices).quality;
        refit_ms += ms_since(start);
        benchmark::DoNotOptimize(floor_nodes.data());
        benchmark::DoNotOptimize(gather_sink.data());
        benchmark::DoNotOptimize(tree.nodes.data());
    }
    const double per_tri = 1e6 / (static_cast<double>(state.iterations()) * static_cast<double>(mesh.triangles.size()));
    state.counters["refit_ns_per_tri"] = refit_ms * per_tri;
    state.counters["floor_ns_per_tri"] = floor_ms * per_tri;
    state.counters["ratio"] = refit_ms / floor_ms;
    state.counters["leaf_gather_ns_per_tri"] = leaf_gather_ms * per_tri;
    state.counters["input_gather_ns_per_tri"] = input_gather_ms * per_tri;
    state.counters["refit_per_leaf_gather"] = refit_ms / leaf_gather_ms;
    state.counters["nodes"] = static_cast<double>(tree.nodes.size());
    state.counters["quality"] = quality;
}

void BM_refit_sheet_1M(benchmark::State& state) {
    static Mesh mesh = [] { Mesh m = sheet_mesh(708); deform(m, 3.0); return m; }();
    run_refit(state, mesh);
}

void BM_refit_dragon(benchmark::State& state) {
    static Mesh mesh = [] { Mesh m = dragon_mesh(); deform(m, 0.002); return m; }();
    run_refit(state, mesh);
}

BENCHMARK(BM_refit_sheet_1M)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_refit_dragon)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
