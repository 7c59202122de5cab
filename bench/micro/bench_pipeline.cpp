// The pipeline with the brute method on the built-in demo scene: milliseconds per frame and
// per stage, with the frame's counts, on a frame apart (object level culls everything) and on
// frames where the sheet cuts the torus.
//
//   build/bench/bench_pipeline [--benchmark_min_time=1] [--benchmark_repetitions=5]
//
// Counters per iteration: cull_ms and narrow_ms (the stats' own stage times), box_tests,
// candidate_pairs and colliding_pairs.

#include "collidescope/datasets.hpp"
#include "collidescope/pipeline.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace collidescope;

void BM_brute_demo_frame(benchmark::State& state) {
    const Scene scene = make_builtin_scene("demo");
    const Frame frame = scene.source->frame(static_cast<std::uint32_t>(state.range(0)));
    Pipeline pipeline({"brute", false, static_cast<int>(state.range(1))});
    pipeline.process(frame);  // warm-up: TBB's threads start
    FrameStats sum;
    for (auto _ : state) {
        const FrameResult result = pipeline.process(frame);
        benchmark::DoNotOptimize(result.colliding_pairs.data());
        sum.ms.cull += result.stats.ms.cull;
        sum.ms.narrow += result.stats.ms.narrow;
        sum.counts = result.stats.counts;
    }
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["cull_ms"] = sum.ms.cull / iterations;
    state.counters["narrow_ms"] = sum.ms.narrow / iterations;
    state.counters["box_tests"] = static_cast<double>(sum.counts.box_tests);
    state.counters["candidate_pairs"] = static_cast<double>(sum.counts.candidate_pairs);
    state.counters["colliding_pairs"] = static_cast<double>(sum.counts.colliding_pairs);
}

// Arguments: frame, threads (0 = all). Frame 0 is apart; 22 and 30 collide.
BENCHMARK(BM_brute_demo_frame)
    ->ArgNames({"frame", "threads"})
    ->Args({0, 0})
    ->Args({22, 1})
    ->Args({22, 0})
    ->Args({30, 1})
    ->Args({30, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
