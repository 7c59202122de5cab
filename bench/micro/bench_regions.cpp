// The regions (find_regions and the tracker) against the pipeline's own frame on a built-in
// scene, in one process: the ratio issue 38 point 6 bounds (the regions at most 25% of a
// `check` frame), without the process start-up that `check --regions` timings carry.
//
//   build/bench/bench_regions [--benchmark_filter=demo] [--benchmark_repetitions=5]
//
// Each benchmark runs every frame of the scene that collides, once per iteration: `check`
// (the pipeline, method adaptive, as `check` runs it; `check_all_frames` every frame) or the regions of those frames' pairs,
// whole or with parts switched off (no curves; no penetration measure). Counter
// `frames`: the colliding frames; `pairs`: their colliding pairs.

#include "collidescope/datasets.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/regions.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

namespace {

using namespace collidescope;

struct Collected {
    std::vector<Frame> all;     ///< every frame
    std::vector<Frame> frames;  ///< the colliding ones
    std::vector<std::vector<TrianglePair>> pairs;
    std::size_t total_pairs = 0;
};

// The scene's colliding frames and their pairs, run once through the pipeline.
const Collected& collected(const std::string& scene_name) {
    static std::string name;
    static Collected kept;
    if (name == scene_name) return kept;
    name = scene_name;
    kept = {};
    const Scene scene = make_builtin_scene(scene_name);
    Pipeline pipeline({"adaptive", scene.self_collision, 0});
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        Frame frame = scene.source->frame(f);
        FrameResult result = pipeline.process(frame);
        kept.all.push_back(frame);
        if (result.colliding_pairs.empty()) continue;
        kept.total_pairs += result.colliding_pairs.size();
        kept.frames.push_back(std::move(frame));
        kept.pairs.push_back(std::move(result.colliding_pairs));
    }
    return kept;
}

void counters(benchmark::State& state, const Collected& c) {
    state.counters["frames"] = static_cast<double>(c.frames.size());
    state.counters["pairs"] = static_cast<double>(c.total_pairs);
}

// `all`: every frame of the scene (what `check` runs); otherwise the colliding ones.
void check_frames(benchmark::State& state, const std::string& scene_name, bool all) {
    const Collected& c = collected(scene_name);
    const std::vector<Frame>& frames = all ? c.all : c.frames;
    const Scene scene = make_builtin_scene(scene_name);
    Pipeline pipeline({"adaptive", scene.self_collision, static_cast<int>(state.range(0))});
    for (const Frame& frame : frames) pipeline.process(frame);  // warm: trees built, threads up
    for (auto _ : state) {
        for (const Frame& frame : frames) benchmark::DoNotOptimize(pipeline.process(frame).colliding_pairs.data());
    }
    counters(state, c);
}

void regions_frames(benchmark::State& state, const std::string& scene_name, RegionOptions options) {
    const Collected& c = collected(scene_name);
    const Scene scene = make_builtin_scene(scene_name);
    Pipeline pipeline({"adaptive", scene.self_collision, static_cast<int>(state.range(0))});  // the thread limit
    for (auto _ : state) {
        RegionTracker tracker;
        for (std::size_t k = 0; k < c.frames.size(); ++k) {
            std::vector<Region> regions = find_regions(c.frames[k], c.pairs[k], options);
            tracker.update(c.frames[k].index, regions);
            benchmark::DoNotOptimize(regions.data());
        }
    }
    counters(state, c);
}

// As `check --regions` runs them: each frame through the pipeline, then its regions (what the
// pipeline leaves in the caches is what the regions start from). Less `check_all_frames`: what
// the regions add.
void check_and_regions(benchmark::State& state, const std::string& scene_name) {
    const Collected& c = collected(scene_name);
    const Scene scene = make_builtin_scene(scene_name);
    Pipeline pipeline({"adaptive", scene.self_collision, static_cast<int>(state.range(0))});
    for (const Frame& frame : c.all) pipeline.process(frame);
    double check_ms = 0, regions_ms = 0;
    for (auto _ : state) {
        RegionTracker tracker;
        for (const Frame& frame : c.all) {
            const auto start = std::chrono::steady_clock::now();
            const FrameResult result = pipeline.process(frame);
            const auto checked = std::chrono::steady_clock::now();
            std::vector<Region> regions = find_regions(frame, result.colliding_pairs);
            tracker.update(frame.index, regions);
            benchmark::DoNotOptimize(regions.data());
            check_ms += std::chrono::duration<double, std::milli>(checked - start).count();
            regions_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - checked).count();
        }
    }
    counters(state, c);
    // Per iteration: the two parts' own times, and the regions over check (what `check
    // --regions` reports as the regions' cost).
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["check_ms"] = check_ms / iterations;
    state.counters["regions_ms"] = regions_ms / iterations;
    state.counters["regions_over_check"] = regions_ms / check_ms;
}

void register_scene(const std::string& scene) {
    const auto add = [&](const std::string& what, auto function) {
        benchmark::RegisterBenchmark((scene + "/" + what).c_str(), function)
            ->ArgName("threads")
            ->Arg(1)
            ->Arg(0)
            ->Unit(benchmark::kMillisecond);
    };
    add("check_all_frames", [scene](benchmark::State& state) { check_frames(state, scene, true); });
    add("check", [scene](benchmark::State& state) { check_frames(state, scene, false); });
    add("check_and_regions", [scene](benchmark::State& state) { check_and_regions(state, scene); });
    add("regions", [scene](benchmark::State& state) { regions_frames(state, scene, {}); });
    add("regions_no_penetration", [scene](benchmark::State& state) { regions_frames(state, scene, {true, false}); });
    add("regions_no_curves_no_penetration",
        [scene](benchmark::State& state) { regions_frames(state, scene, {false, false}); });
}

}  // namespace

int main(int argc, char** argv) {
    for (const char* scene : {"demo", "A", "B", "E2", "cloth-drape", "cloth-slide", "coplanar-stack"}) register_scene(scene);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
