// Peers on the data sets' frames: Embree 3 rtcCollide (user geometries, refit build quality
// on a dynamic scene) and FCL 0.7 (BVHModel<AABB>, refit, exhaustive contacts), next to the
// `aabb` method, between objects (self-collision off: neither peer does it). Per data set:
// ms per frame of each, and how each peer's pairs differ from the exact ones (missed exact
// pairs, extra pairs). Embree reports box-overlap candidates (float boxes), FCL its own
// floating-point triangle test. So `embree_broad_phase_ms` times a BROAD PHASE ALONE (refit
// and rtcCollide, no exact test), against the whole `aabb` method and FCL's whole query: not a
// like-for-like comparison; bench/peers/bench_embree_cgal_peers.cpp (Embree plus an exact
// narrow phase) is. All three run in one process here, on all hardware threads; the fair,
// process-per-run comparison is bench/scripts/peers_fair.py. Built only when both packages
// are installed (bench/CMakeLists).
//
//   build-bvh/bench/bench_bvh_peers [--benchmark_filter=C]

#include "peers/embree_peer.hpp"
#include "peers/fcl_peer.hpp"
#include "peers/peer_common.hpp"

#include "methods/aabb_method.hpp"
#include "stages/object_level.hpp"

#include "collidescope/datasets.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace collidescope;
using namespace collidescope::peers;

const char* const k_sets[] = {"A", "B", "C", "D", "E1", "E2", "E3", "E4"};

void BM_peers(benchmark::State& state) {
    const Scene scene = make_builtin_scene(k_sets[state.range(0)]);
    const std::uint32_t frames = std::min<std::uint32_t>(scene.source->frame_count(), static_cast<std::uint32_t>(state.range(1)));
    state.SetLabel(k_sets[state.range(0)]);
    double ours_ms = 0, embree_ms = 0, fcl_ms = 0;
    std::size_t exact_pairs = 0, embree_extra = 0, embree_missed = 0, fcl_extra = 0, fcl_missed = 0;
    for (auto _ : state) {
        const std::unique_ptr<Method> ours = make_aabb_method();
        EmbreePeer embree;
        FclPeer fcl_peer;
        for (std::uint32_t f = 0; f < frames; ++f) {
            const Frame frame = scene.source->frame(f);
            Clock::time_point start = Clock::now();
            const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
            const std::vector<ObjectPair> object_pairs = find_object_pairs(boxes, false);
            PairSet exact;
            FrameStats stats;
            ours->detect({frame, boxes, object_pairs, false}, exact, stats);
            std::sort(exact.begin(), exact.end());
            exact.erase(std::unique(exact.begin(), exact.end()), exact.end());
            ours_ms += ms_since(start);
            start = Clock::now();
            embree.update(frame);
            const PairSet from_embree = embree.candidates(object_pairs);
            embree_ms += ms_since(start);
            start = Clock::now();
            const PairSet from_fcl = fcl_peer.frame(frame, object_pairs);
            fcl_ms += ms_since(start);
            exact_pairs += exact.size();
            const auto [e_extra, e_missed] = difference(from_embree, exact);
            const auto [f_extra, f_missed] = difference(from_fcl, exact);
            embree_extra += e_extra;
            embree_missed += e_missed;
            fcl_extra += f_extra;
            fcl_missed += f_missed;
        }
    }
    state.counters["aabb_ms"] = ours_ms / frames;
    state.counters["embree_broad_phase_ms"] = embree_ms / frames;  // no narrow phase
    state.counters["fcl_ms"] = fcl_ms / frames;
    state.counters["exact_pairs"] = static_cast<double>(exact_pairs);
    state.counters["embree_extra"] = static_cast<double>(embree_extra);
    state.counters["embree_missed"] = static_cast<double>(embree_missed);
    state.counters["fcl_extra"] = static_cast<double>(fcl_extra);
    state.counters["fcl_missed"] = static_cast<double>(fcl_missed);
}

// Arguments: data set, frames (the first N; each frame's peers refit from the last).
BENCHMARK(BM_peers)
    ->ArgNames({"set", "frames"})
    ->Args({0, 50})->Args({1, 50})->Args({2, 50})->Args({3, 50})->Args({4, 25})->Args({5, 50})->Args({6, 50})
    ->Args({7, 50})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
