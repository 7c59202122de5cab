// Self-collision culling (issue 23): what testing a cloth against itself costs beyond its
// refit. Per frame of a built-in cloth scene, the same tree layout twice:
//  - plain: refit only (what the frame costs an object not tested against itself);
//  - self: refit with surface patches (the projected orientations), then the self-traversal
//    from the root and the exact self rule on every candidate it hands over.
// self_cost = self - plain refit; the target is self_cost <= 1x refit, i.e. self-collision at
// most 2x the refit in all ("Self-collision of a flat 1M-triangle cloth at rest costs at
// most 2x its refit").
//
//   build/bench/bench_self_cull [--benchmark_repetitions=5]
//
// BM_build_*: a build with and without the patches.
// Counters: refit_ms, self_ms (refit with patches + traversal + narrow), self_over_refit
// (self_ms / refit_ms), culled (triangles below nodes proven embedded), candidates, colliding.

#include "bvh/bvh.hpp"
#include "bvh/traverse.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/geometry.hpp"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <map>
#include <string>

namespace {

using namespace collidescope;
using Clock = std::chrono::steady_clock;

struct SceneFrames {
    std::vector<TriIndices> triangles;
    std::vector<std::vector<Vec3>> frames;
};

const SceneFrames& scene_frames(const std::string& spec) {
    static std::map<std::string, SceneFrames> cache;
    auto [it, fresh] = cache.try_emplace(spec);
    if (fresh) {
        const Scene scene = make_builtin_scene(spec);
        for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
            const Frame frame = scene.source->frame(f);
            if (f == 0) it->second.triangles = frame.objects[0].topology->triangles;
            it->second.frames.push_back(frame.objects[0].vertices.to_vector());
        }
    }
    return it->second;
}

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void run_self(benchmark::State& state, const std::string& spec) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(0)));
    const SceneFrames& mesh = scene_frames(spec);
    bvh::Tree plain, patched;
    bvh::build_tree(mesh.triangles, mesh.frames[0], bvh::BuildConfig{}, plain);
    bvh::BuildConfig with_patches;
    with_patches.surface_patches = true;
    bvh::build_tree(mesh.triangles, mesh.frames[0], with_patches, patched);
    double refit_ms = 0, self_ms = 0;
    std::uint64_t culled = 0, candidates = 0, colliding = 0;
    std::size_t k = 0;
    std::vector<TrianglePair> pairs;
    for (auto _ : state) {
        const std::vector<Vec3>& vertices = mesh.frames[k++ % mesh.frames.size()];
        Clock::time_point start = Clock::now();
        bvh::refit(plain, mesh.triangles, vertices);
        refit_ms += ms_since(start);
        start = Clock::now();
        bvh::refit(patched, mesh.triangles, vertices);
        const bvh::MeshView view{&patched, mesh.triangles, vertices, {}, {}};
        pairs.clear();
        const bvh::TraversalStats stats = bvh::traverse({{0, 0, 0, 0}}, std::span(&view, 1), {}, pairs);
        for (const TrianglePair& pair : pairs) {
            const TriIndices& a = mesh.triangles[pair.tri_a];
            const TriIndices& b = mesh.triangles[pair.tri_b];
            colliding += self_triangles_collide(a, {vertices[a[0]], vertices[a[1]], vertices[a[2]]}, b,
                                                {vertices[b[0]], vertices[b[1]], vertices[b[2]]});
        }
        self_ms += ms_since(start);
        culled += stats.self_culled_triangles;
        candidates += stats.candidate_pairs;
        benchmark::DoNotOptimize(plain.nodes.data());
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["refit_ms"] = refit_ms / n;
    state.counters["self_ms"] = self_ms / n;
    state.counters["self_over_refit"] = self_ms / refit_ms;
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    state.counters["culled"] = static_cast<double>(culled) / n;
    state.counters["candidates"] = static_cast<double>(candidates) / n;
    state.counters["colliding"] = static_cast<double>(colliding) / n;
}

// A build with and without surface patches (what a policy rebuild of a self-colliding object
// costs beyond the tree itself). Counters: plain_ms, patches_ms, patches_over_plain.
void run_build(benchmark::State& state, const std::string& spec) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(0)));
    const SceneFrames& mesh = scene_frames(spec);
    bvh::BuildConfig with_patches;
    with_patches.surface_patches = true;
    double plain_ms = 0, patches_ms = 0;
    for (auto _ : state) {
        bvh::Tree tree;
        Clock::time_point start = Clock::now();
        bvh::build_tree(mesh.triangles, mesh.frames[0], bvh::BuildConfig{}, tree);
        plain_ms += ms_since(start);
        start = Clock::now();
        bvh::build_tree(mesh.triangles, mesh.frames[0], with_patches, tree);
        patches_ms += ms_since(start);
        benchmark::DoNotOptimize(tree.nodes.data());
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["plain_ms"] = plain_ms / n;
    state.counters["patches_ms"] = patches_ms / n;
    state.counters["patches_over_plain"] = patches_ms / plain_ms;
}

void BM_build_cloth_drape_large(benchmark::State& state) { run_build(state, "cloth-drape:large"); }
BENCHMARK(BM_build_cloth_drape_large)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_self_cloth_rest_large(benchmark::State& state) { run_self(state, "cloth-rest:large"); }
void BM_self_cloth_drape_large(benchmark::State& state) { run_self(state, "cloth-drape:large"); }
void BM_self_cloth_crumple_large(benchmark::State& state) { run_self(state, "cloth-crumple:large"); }

BENCHMARK(BM_self_cloth_rest_large)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_self_cloth_drape_large)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_self_cloth_crumple_large)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
