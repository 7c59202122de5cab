// The `aabb` method on every data set and the cloth family (default preset, all frames): milliseconds per frame,
// split into stages (refit, rebuild, traversal, narrow), rebuilds and tree quality, next to
// brute force on sampled frames (brute keeps no state, so sampling is fair) and the ratio.
//
//   build-bvh/bench/bench_bvh_datasets [--benchmark_filter=C/] [--benchmark_counters_tabular=true]
//
// Variants (second argument):
//   0 brute          every 20th frame (brute is too slow for all frames of every set)
//   1 aabb           the registry's default: LBVH, quality rule 1.5, background rebuild
//   2 aabb_sah       the same with the SAH builder
//   3 aabb_thesis    thesis 5.2.1 rule (rebuild when detection > 3/4 of a rebuild), background
//   4 every_frame_lbvh / 5 every_frame_sah: rebuild every frame on the engine thread, which
//     decides which builder wins as the rebuild of a deforming mesh
// Only the object level and the method are timed; generating the frames is not.

#include "stages/object_level.hpp"
#include "methods/aabb_method.hpp"
#include "methods/brute_method.hpp"

#include "collidescope/datasets.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <iterator>
#include <map>

namespace {

using namespace collidescope;

// The thesis's data sets, then the cloth family (issue 23: self-contact, coplanar contact).
const char* const k_sets[] = {"A", "B", "C", "D", "E1", "E2", "E3", "E4", "cloth-rest",
                              "cloth-drape", "cloth-crumple", "cloth-slide"};
const char* const k_variants[] = {"brute", "aabb", "aabb_sah", "aabb_thesis", "every_frame_lbvh", "every_frame_sah"};

std::unique_ptr<Method> make_variant(std::int64_t variant) {
    if (variant == 0) return make_brute_method();
    bvh::AabbConfig config;
    if (variant == 2 || variant == 5) config.build.builder = bvh::Builder::Sah;
    if (variant == 3) config.policy.rule = bvh::RebuildRule::Thesis;
    if (variant >= 4) {
        config.policy.quality_limit = -1;  // any quality exceeds it: rebuild every frame
        config.policy.payback_frames = 0;
        config.background = bvh::BackgroundMode::Off;
    }
    return make_aabb_method(config);
}

std::map<std::int64_t, double>& brute_ms_per_frame() {
    static std::map<std::int64_t, double> ms;
    return ms;
}

struct Totals {
    FrameStats sum;
    double ms = 0;
    double max_quality = 0;
    double quality_sum = 0;
    std::uint32_t frames = 0;
};

void run_frame(Method& method, const Frame& frame, bool self_collision, Totals& totals) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
    const std::vector<ObjectPair> object_pairs = find_object_pairs(boxes, self_collision);
    std::vector<TrianglePair> pairs;
    FrameStats stats;
    method.detect({frame, boxes, object_pairs, self_collision}, pairs, stats);
    totals.ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    totals.sum.ms.refit += stats.ms.refit;
    totals.sum.ms.rebuild += stats.ms.rebuild;
    totals.sum.ms.traversal += stats.ms.traversal;
    totals.sum.ms.narrow += stats.ms.narrow;
    totals.sum.counts.rebuilds += stats.counts.rebuilds;
    totals.sum.counts.colliding_pairs += stats.counts.colliding_pairs;
    totals.sum.counts.candidate_pairs += stats.counts.candidate_pairs;
    totals.sum.counts.nodes_visited += stats.counts.nodes_visited;
    if (stats.aabb) {
        totals.max_quality = std::max(totals.max_quality, stats.aabb->tree_quality);
        totals.quality_sum += stats.aabb->tree_quality;
    }
    ++totals.frames;
}

void BM_dataset(benchmark::State& state) {
    const std::int64_t set = state.range(0);
    const std::int64_t variant = state.range(1);
    const Scene scene = make_builtin_scene(k_sets[set]);
    state.SetLabel(std::string(k_sets[set]) + " " + k_variants[variant] + (scene.self_collision ? " self" : ""));
    Totals totals;
    for (auto _ : state) {
        const std::unique_ptr<Method> method = make_variant(variant);
        const std::uint32_t stride = variant == 0 ? 20 : 1;
        for (std::uint32_t f = 0; f < scene.source->frame_count(); f += stride) {
            state.PauseTiming();
            const Frame frame = scene.source->frame(f);
            state.ResumeTiming();
            run_frame(*method, frame, scene.self_collision, totals);
        }
    }
    const double frames = totals.frames;
    state.counters["ms_per_frame"] = totals.ms / frames;
    state.counters["refit_ms"] = totals.sum.ms.refit / frames;
    state.counters["rebuild_ms"] = totals.sum.ms.rebuild / frames;
    state.counters["traversal_ms"] = totals.sum.ms.traversal / frames;
    state.counters["narrow_ms"] = totals.sum.ms.narrow / frames;
    state.counters["rebuilds"] = static_cast<double>(totals.sum.counts.rebuilds);
    state.counters["pairs_per_frame"] = static_cast<double>(totals.sum.counts.colliding_pairs) / frames;
    state.counters["quality_mean"] = totals.quality_sum / frames;
    state.counters["quality_max"] = totals.max_quality;
    if (variant == 0) brute_ms_per_frame()[set] = totals.ms / frames;
    if (variant != 0 && brute_ms_per_frame().count(set) != 0) {
        state.counters["brute_ratio"] = brute_ms_per_frame()[set] / (totals.ms / frames);
    }
}

void all_sets(benchmark::internal::Benchmark* bench) {
    for (std::int64_t set = 0; set < static_cast<std::int64_t>(std::size(k_sets)); ++set) {
        for (std::int64_t variant = 0; variant < 6; ++variant) bench->Args({set, variant});
    }
}

BENCHMARK(BM_dataset)->ArgNames({"set", "variant"})->Apply(all_sets)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
