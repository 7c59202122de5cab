// Animation evaluation (issue 28, item 9): linear blend skinning of a 1,000,000-vertex mesh
// with 4 influences per vertex (target: <= 20 ms per frame on one thread, scaling with
// threads), and, on real skinned characters, the share of a `check --method aabb --self`
// frame spent posing the model.
//
//   build/bench/bench_animation                       # both
//   build/bench/bench_animation --benchmark_filter=Skin
//   COLLIDESCOPE_CHARACTER=/path/model.fbx build/bench/bench_animation --benchmark_filter=Share
//
// Skin: the Time column (real time) is ms per frame; with one thread the CPU column is the
// calling thread's own compute time (TBB runs the loop on it), robust to a loaded machine.
// Share: eval_ms (FrameSource::frame: sampling, skinning, the finiteness check, the copy),
// check_ms (Pipeline::process with aabb and self-collision), share = eval / (eval + check).

#include "mesh/skinning.hpp"

#include "collidescope/pipeline.hpp"
#include "collidescope/scene.hpp"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace {

using namespace collidescope;
using namespace collidescope::animation;
using Clock = std::chrono::steady_clock;

struct SkinnedMesh {
    std::vector<Vec3> rest;
    std::vector<std::uint32_t> begin, bone;
    std::vector<double> weight;
    std::vector<Affine> bones;
};

// 1M vertices, 4 influences each over 64 bones, random weights normalised; bones rotated and
// translated so no matrix is trivial. Seed 28.
SkinnedMesh make_mesh(std::size_t vertices, int influences, int bones) {
    std::mt19937 rng(28);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(bones - 1));
    SkinnedMesh mesh;
    mesh.begin.push_back(0);
    for (std::size_t v = 0; v < vertices; ++v) {
        mesh.rest.emplace_back(unit(rng), unit(rng), unit(rng));
        double sum = 0;
        const std::size_t first = mesh.weight.size();
        for (int i = 0; i < influences; ++i) {
            mesh.bone.push_back(pick(rng));
            mesh.weight.push_back(unit(rng) + 0.01);
            sum += mesh.weight.back();
        }
        for (std::size_t i = first; i < mesh.weight.size(); ++i) mesh.weight[i] /= sum;
        mesh.begin.push_back(static_cast<std::uint32_t>(mesh.bone.size()));
    }
    for (int b = 0; b < bones; ++b) {
        const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
        Affine m;
        m.leftCols<3>() = q.toRotationMatrix();
        m.col(3) = Vec3(unit(rng), unit(rng), unit(rng));
        mesh.bones.push_back(m);
    }
    return mesh;
}

void BM_Skin1M4Influences(benchmark::State& state) {
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(state.range(0)));
    static const SkinnedMesh mesh = make_mesh(1'000'000, 4, 64);
    std::vector<Vec3> out(mesh.rest.size());
    const Influences influences{mesh.begin, mesh.bone, mesh.weight};
    for (auto _ : state) {
        skin(mesh.rest, influences, mesh.bones, Affine::Identity(), out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.counters["threads"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_Skin1M4Influences)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Posing vs checking, frame by frame over the whole clip (30 fps), on one character.
void BM_CharacterEvaluationShare(benchmark::State& state) {
    const char* env = std::getenv("COLLIDESCOPE_CHARACTER");
    const std::string file = env != nullptr ? env : "/usr/share/assimp/models/X/BCN_Epileptic.X";
    if (!std::filesystem::exists(file)) {
        state.SkipWithError(("no character at " + file).c_str());
        return;
    }
    const std::vector<std::string> inputs{file};
    double eval_ms = 0, check_ms = 0;
    std::size_t frames = 0;
    for (auto _ : state) {
        Scene scene = open_inputs(inputs);
        PipelineConfig config;
        config.method = "aabb";
        config.self_collision = true;
        Pipeline pipeline(config);
        for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
            const auto t0 = Clock::now();
            const Frame frame = scene.source->frame(f);
            const auto t1 = Clock::now();
            benchmark::DoNotOptimize(pipeline.process(frame));
            const auto t2 = Clock::now();
            eval_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
            check_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
            ++frames;
        }
    }
    state.counters["frames"] = static_cast<double>(frames);
    state.counters["eval_ms"] = eval_ms / static_cast<double>(frames);
    state.counters["check_ms"] = check_ms / static_cast<double>(frames);
    state.counters["share"] = eval_ms / (eval_ms + check_ms);
}
BENCHMARK(BM_CharacterEvaluationShare)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
