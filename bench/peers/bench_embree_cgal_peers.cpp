// The peer users would assemble for cloth-like scenes (issue 23, item 4): Embree 3 (refit
// BVH, rtcCollide of each object with itself and with the others) for the broad phase, then
// CGAL's filtered exact predicates, on TBB's threads as the engine's narrow phase (until
// 2026-11-27: sequentially), with DESIGN.md's self rule
// (peers/cgal_narrow_phase.hpp); beside the `aabb` method at several thread counts and FCL
// (objects only: FCL has no self-collision). One scene per run, on chosen frames; every
// method sees the same frames in the same order, after one warm-up frame (the first chosen
// frame, processed whole: builds the trees and grows the buffers) that is not timed.
//
// Prints one JSON object per run on stdout: ms per frame are means over the timed frames;
// narrow_split is each exact test's time alone, one thread, on the candidates that share a
// vertex index and on the others (untimed elsewhere). Checks that the peer's pairs equal the
// `aabb` method's on every timed frame: counts of extra and missed pairs, never hidden (exit
// status 2 when any).
//
//   build/bench/bench_embree_cgal_peers --scene cloth-rest:large [--self on|off|scene]
//       [--frames 0,3,7 | --frames all] [--threads 1,2] [--no-fcl | --fcl-frames K]
//       [--embree-build refit|low|medium] [--no-split] [--only aabb|peer|fcl]
//
// --only runs one side alone in this process, on the first --threads count, and prints its
// ms and a digest of its pairs (FNV-1a over every timed frame's sorted pairs): the fair
// comparison (bench/scripts/peers_fair.py) runs each side in a process of its own, in
// alternating order, several times, and compares the digests. Every side runs on the same
// number of threads: the engine under its thread limit, the peer's Embree builds under
// Embree's `threads` setting and its CGAL narrow phase and FCL's object pairs under a
// tbb::global_control of that many threads (without --only: the largest --threads count).
//   build/bench/bench_embree_cgal_peers INPUT... [the same options]
//       (your own scene: any inputs `collidescope check` takes, a scene.json manifest, frame
//       patterns, mesh files with point caches; --self scene follows the manifest)
//   build/bench/bench_embree_cgal_peers --check-rule 1000000
//       (the peer's exact test against the engine's on random pairs of one object whose
//       corners lie on a 3x3x3 grid, with shared indices: degenerate, coplanar, touching)
//
// Built only when Embree 3, FCL and CGAL are installed (bench/CMakeLists.txt).

#include "peers/cgal_narrow_phase.hpp"
#include "peers/embree_peer.hpp"
#include "peers/fcl_peer.hpp"

#include "stages/narrow_phase.hpp"
#include "stages/object_level.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/memory.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/scene.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

using namespace collidescope;
using namespace collidescope::peers;

struct Options {
    std::string scene = "cloth-rest:large";
    std::vector<std::string> inputs;       // non-empty: these inputs instead of a built-in scene
    std::string self = "on";               // on, off, or the scene's default
    std::vector<std::uint32_t> frames;     // empty: 5 frames spread over the animation
    bool every_frame = false;              // --frames all: every frame, in order
    std::vector<int> threads = {1, 2};     // thread counts of the `aabb` runs
    bool fcl = true;
    RTCBuildQuality embree_quality = RTC_BUILD_QUALITY_REFIT;  // --embree-build refit|low|medium
    bool split = true;                     // --no-split: skip narrow_split
    std::size_t fcl_frames = 0;            // > 0: FCL on the first this many timed frames only
    std::uint64_t check_rule = 0;          // > 0: only compare the exact tests on this many pairs
    std::string only;                      // "", aabb, peer or fcl: that side alone (see the top)
};

std::vector<std::uint32_t> parse_list(const std::string& text) {
    std::vector<std::uint32_t> out;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');) out.push_back(static_cast<std::uint32_t>(std::stoul(item)));
    return out;
}

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--scene") options.scene = value();
        else if (arg == "--self") options.self = value();
        else if (arg == "--frames") {
            const std::string list = value();
            options.every_frame = list == "all";
            if (!options.every_frame) options.frames = parse_list(list);
        }
        else if (arg == "--threads") {
            options.threads.clear();
            for (std::uint32_t t : parse_list(value())) options.threads.push_back(static_cast<int>(t));
        } else if (arg == "--no-fcl") options.fcl = false;
        else if (arg == "--embree-build") {
            const std::string v = value();
            if (v != "low" && v != "medium" && v != "refit")
                throw std::invalid_argument("--embree-build: refit, low or medium");
            options.embree_quality = v == "low"      ? RTC_BUILD_QUALITY_LOW
                                     : v == "medium" ? RTC_BUILD_QUALITY_MEDIUM
                                                     : RTC_BUILD_QUALITY_REFIT;
        } else if (arg == "--no-split") options.split = false;
        else if (arg == "--fcl-frames") options.fcl_frames = std::stoul(value());
        else if (arg == "--check-rule") options.check_rule = std::stoull(value());
        else if (arg == "--only") {
            options.only = value();
            if (options.only != "aabb" && options.only != "peer" && options.only != "fcl")
                throw std::invalid_argument("--only: aabb, peer or fcl");
        }
        else if (!arg.starts_with("--")) options.inputs.push_back(arg);
        else throw std::invalid_argument("unknown argument " + arg);
    }
    return options;
}

volatile std::size_t benchmark_sink = 0;  // keeps timed loops from being optimised away

std::vector<std::uint32_t> spread_frames(std::uint32_t count, std::uint32_t wanted) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t k = 0; k < wanted; ++k) out.push_back(count <= 1 ? 0 : k * (count - 1) / (wanted - 1));
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

/// FNV-1a over every frame's pairs, sorted and unique, frame after frame: equal digests, equal
/// pairs on every timed frame (what the fair comparison's separate processes compare).
std::uint64_t pairs_digest(const std::vector<PairSet>& frames) {
    std::uint64_t hash = 1469598103934665603ull;
    const auto mix = [&hash](std::uint64_t value) {
        for (int byte = 0; byte < 8; ++byte) {
            hash ^= (value >> (8 * byte)) & 0xFF;
            hash *= 1099511628211ull;
        }
    };
    for (PairSet pairs : frames) {
        sort_unique(pairs);
        mix(pairs.size());
        for (const TrianglePair& p : pairs) {
            mix((std::uint64_t{p.obj_a} << 32) | p.tri_a);
            mix((std::uint64_t{p.obj_b} << 32) | p.tri_b);
        }
    }
    return hash;
}

/// Means over the timed frames of one `aabb` run.
struct OursRun {
    int threads = 0;
    double total_ms = 0, refit_ms = 0, rebuild_ms = 0, traversal_ms = 0, narrow_ms = 0;
    double candidates = 0, exact_tests = 0, exact_fallbacks = 0, colliding = 0;
};

OursRun run_ours(const std::vector<Frame>& frames, bool self, int threads, std::vector<PairSet>& pairs) {
    PipelineConfig config;
    config.method = "aabb";
    config.self_collision = self;
    config.threads = threads;
    Pipeline pipeline(config);  // its thread limit holds while it lives
    pipeline.process(frames.front());  // warm-up: builds the trees, grows the buffers
    OursRun run;
    run.threads = threads;
    pairs.clear();
    for (const Frame& frame : frames) {
        FrameResult result = pipeline.process(frame);
        const FrameStats& s = result.stats;
        run.total_ms += s.ms.total;
        run.refit_ms += s.ms.refit;
        run.rebuild_ms += s.ms.rebuild;
        run.traversal_ms += s.ms.traversal;
        run.narrow_ms += s.ms.narrow;
        run.candidates += static_cast<double>(s.counts.candidate_pairs);
        run.exact_tests += static_cast<double>(s.counts.exact_tests);
        run.exact_fallbacks += static_cast<double>(s.counts.exact_fallbacks);
        run.colliding += static_cast<double>(s.counts.colliding_pairs);
        pairs.push_back(std::move(result.colliding_pairs));
    }
    const double n = static_cast<double>(frames.size());
    for (double* x : {&run.total_ms, &run.refit_ms, &run.rebuild_ms, &run.traversal_ms, &run.narrow_ms,
                      &run.candidates, &run.exact_tests, &run.exact_fallbacks, &run.colliding})
        *x /= n;
    return run;
}

/// The peer's TBB threads (its CGAL narrow phase, FCL's object pairs) limited to `threads`, as
/// the engine's are under its thread limit; null (all hardware threads) for 0.
std::unique_ptr<tbb::global_control> thread_limit(int threads) {
    if (threads <= 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                 static_cast<std::size_t>(threads));
}

/// Means over the timed frames of the Embree + CGAL peer, and its differences from `exact`.
struct PeerRun {
    double total_ms = 0, refit_ms = 0, collide_ms = 0, narrow_ms = 0, candidates = 0, colliding = 0;
    std::size_t extra = 0, missed = 0, repeated = 0;  // repeated: candidates Embree gave twice
};

std::vector<ObjectPair> object_pairs(const Frame& frame, bool self) {
    return find_object_pairs(compute_object_boxes(frame), self);
}

PeerRun run_peer(const std::vector<Frame>& frames, bool self, const std::vector<PairSet>& exact,
                 RTCBuildQuality quality, int threads, std::vector<PairSet>* found = nullptr) {
    const std::unique_ptr<tbb::global_control> limit = thread_limit(threads);
    EmbreePeer embree(quality, threads);
    // Warm-up: a whole frame, as the engine's (it builds the trees and grows the threads'
    // candidate lists; with the trees alone, the first timed frame grew the lists in memory
    // never touched before, and the peer's mean collide time on C moved between 2.3 and 7 ms
    // with what the process had allocated earlier).
    embree.update(frames.front());
    cgal_narrow_phase(frames.front(), embree.candidates(object_pairs(frames.front(), self)));
    PeerRun run;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Clock::time_point start = Clock::now();
        const std::vector<ObjectPair> pairs = object_pairs(frames[f], self);
        embree.update(frames[f]);
        const double refit = ms_since(start);
        const PairSet candidates = embree.candidates(pairs);
        const double collide = ms_since(start) - refit;
        PairSet colliding = cgal_narrow_phase(frames[f], candidates);
        const double total = ms_since(start);
        run.total_ms += total;
        run.refit_ms += refit;
        run.collide_ms += collide;
        run.narrow_ms += total - refit - collide;
        run.candidates += static_cast<double>(candidates.size());
        PairSet unique = candidates;
        sort_unique(unique);
        run.repeated += candidates.size() - unique.size();
        run.colliding += static_cast<double>(colliding.size());
        if (found != nullptr) found->push_back(colliding);
        if (f < exact.size()) {
            const auto [extra, missed] = difference(std::move(colliding), exact[f]);
            run.extra += extra;
            run.missed += missed;
        }
    }
    const double n = static_cast<double>(frames.size());
    for (double* x : {&run.total_ms, &run.refit_ms, &run.collide_ms, &run.narrow_ms, &run.candidates, &run.colliding})
        *x /= n;
    return run;
}

/// Where the narrow phases' time goes, per timed frame (means; untimed in the table):
/// candidates within one object that share a vertex index (always box-overlapping, decided by
/// the self rule) against the rest, each set run sequentially through the engine's exact test
/// (stages/narrow_phase.hpp, one thread) and the peer's.
struct AdjacentSplit {
    std::size_t adjacent = 0, other = 0;
    double engine_adjacent_ms = 0, engine_other_ms = 0, cgal_adjacent_ms = 0, cgal_other_ms = 0;
};

bool shares_index(const Frame& frame, const TrianglePair& pair) {
    if (pair.obj_a != pair.obj_b) return false;
    const auto& triangles = frame.objects[pair.obj_a].topology->triangles;
    const TriIndices& a = triangles[pair.tri_a];
    const TriIndices& b = triangles[pair.tri_b];
    for (std::uint32_t i : a)
        if (i == b[0] || i == b[1] || i == b[2]) return true;
    return false;
}

void split_adjacent(const Frame& frame, bool self, AdjacentSplit& split) {
    EmbreePeer embree;
    embree.update(frame);
    PairSet adjacent, other;
    for (const TrianglePair& pair : embree.candidates(object_pairs(frame, self)))
        (shares_index(frame, pair) ? adjacent : other).push_back(pair);
    const auto time = [&](const PairSet& pairs, auto&& test) {
        const Clock::time_point start = Clock::now();
        std::size_t hits = 0;
        for (const TrianglePair& pair : pairs) hits += test(frame, pair) ? 1 : 0;
        benchmark_sink = hits;
        return ms_since(start);
    };
    split.adjacent += adjacent.size();
    split.other += other.size();
    split.engine_adjacent_ms += time(adjacent, pair_collides);
    split.engine_other_ms += time(other, pair_collides);
    split.cgal_adjacent_ms += time(adjacent, cgal_pair_collides);
    split.cgal_other_ms += time(other, cgal_pair_collides);
}

AdjacentSplit split_adjacent(const std::vector<Frame>& frames, bool self) {
    AdjacentSplit split;
    for (const Frame& frame : frames) split_adjacent(frame, self, split);
    const std::size_t n = frames.size();
    split.adjacent /= n;
    split.other /= n;
    for (double* x : {&split.engine_adjacent_ms, &split.engine_other_ms, &split.cgal_adjacent_ms, &split.cgal_other_ms})
        *x /= static_cast<double>(n);
    return split;
}

/// FCL between objects: ms per frame, its pairs, and its differences from the exact pairs
/// between objects. Null when the scene has no pair of distinct objects in the timed frames.
struct FclRun {
    std::size_t frames = 0;  // timed frames (the first ones)
    double total_ms = 0, pairs = 0;
    std::size_t extra = 0, missed = 0;
};

FclRun run_fcl(const std::vector<Frame>& frames, const std::vector<PairSet>& exact, std::size_t count, int threads,
               std::vector<PairSet>* found = nullptr) {
    const std::unique_ptr<tbb::global_control> limit = thread_limit(threads);
    FclPeer fcl_peer;
    fcl_peer.frame(frames.front(), object_pairs(frames.front(), false));  // warm-up
    FclRun run;
    run.frames = count;
    for (std::size_t f = 0; f < count; ++f) {
        const Clock::time_point start = Clock::now();
        const PairSet pairs = fcl_peer.frame(frames[f], object_pairs(frames[f], false));
        run.total_ms += ms_since(start);
        run.pairs += static_cast<double>(pairs.size());
        if (found != nullptr) found->push_back(pairs);
        if (f >= exact.size()) continue;
        PairSet between;
        for (const TrianglePair& p : exact[f])
            if (p.obj_a != p.obj_b) between.push_back(p);
        const auto [extra, missed] = difference(pairs, between);
        run.extra += extra;
        run.missed += missed;
    }
    run.total_ms /= static_cast<double>(count);
    run.pairs /= static_cast<double>(count);
    return run;
}

std::string json_ours(const OursRun& r) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "{\"threads\": %d, \"ms\": %.3f, \"refit_ms\": %.3f, \"rebuild_ms\": %.3f, \"traversal_ms\": %.3f, "
                  "\"narrow_ms\": %.3f, \"candidates\": %.0f, \"exact_tests\": %.0f, \"exact_fallbacks\": %.0f, "
                  "\"colliding\": %.0f}",
                  r.threads, r.total_ms, r.refit_ms, r.rebuild_ms, r.traversal_ms, r.narrow_ms, r.candidates,
                  r.exact_tests, r.exact_fallbacks, r.colliding);
    return text;
}

/// Random pairs of triangles of one object, six vertices on a 3x3x3 grid (so degenerate,
/// coplanar, touching and repeated corners are common), indices drawn from those six (so
/// pairs share zero to three indices): counts where CGAL's verdict differs from the engine's.
int check_rule(std::uint64_t pairs) {
    std::mt19937_64 random(23);
    std::uniform_int_distribution<int> coordinate(0, 2), index(0, 5);
    auto topology = std::make_shared<Topology>();
    topology->vertex_count = 6;
    topology->triangles.resize(2);
    Frame frame;
    frame.objects.push_back({topology, std::vector<Vec3>(6)});
    std::uint64_t differ = 0, hits = 0;
    for (std::uint64_t k = 0; k < pairs; ++k) {
        std::vector<Vec3> vertices(6);
        for (Vec3& v : vertices) v = Vec3(coordinate(random), coordinate(random), coordinate(random));
        frame.objects[0].vertices = std::move(vertices);
        const auto corner = [&] { return static_cast<std::uint32_t>(index(random)); };
        for (TriIndices& t : topology->triangles) t = {corner(), corner(), corner()};
        const TrianglePair pair{0, 0, 0, 1};
        const bool ours = pair_collides(frame, pair);
        hits += ours;
        if (ours != cgal_pair_collides(frame, pair)) ++differ;
    }
    std::cout << "{\"check_rule_pairs\": " << pairs << ", \"colliding\": " << hits << ", \"differ\": " << differ << "}\n";
    return differ == 0 ? 0 : 2;
}

/// --only: one side alone on options.threads.front() threads; one JSON line with its ms per
/// timed frame (mean), its stage split and the digest of its pairs.
int run_one_side(const Options& options, const std::string& scene_name, bool self,
                 const std::vector<std::uint32_t>& indices, const std::vector<Frame>& frames, std::size_t triangles) {
    const int threads = options.threads.front();
    std::vector<PairSet> pairs;
    std::string side;
    if (options.only == "aabb") {
        side = json_ours(run_ours(frames, self, threads, pairs));
    } else if (options.only == "peer") {
        const PeerRun r = run_peer(frames, self, {}, options.embree_quality, threads, &pairs);
        char text[512];
        std::snprintf(text, sizeof text,
                      "{\"threads\": %d, \"ms\": %.3f, \"refit_ms\": %.3f, \"collide_ms\": %.3f, \"narrow_ms\": %.3f, "
                      "\"embree_candidates\": %.0f, \"colliding\": %.0f, \"repeated\": %zu}",
                      threads, r.total_ms, r.refit_ms, r.collide_ms, r.narrow_ms, r.candidates, r.colliding, r.repeated);
        side = text;
    } else {
        if (frames.front().objects.size() < 2) throw std::invalid_argument("--only fcl: the scene has one object (FCL has no self-collision)");
        const FclRun r = run_fcl(frames, {}, frames.size(), threads, &pairs);
        char text[256];
        std::snprintf(text, sizeof text, "{\"threads\": %d, \"ms\": %.3f, \"pairs\": %.0f, \"between_objects_only\": true}",
                      threads, r.total_ms, r.pairs);
        side = text;
    }
    std::string frame_list;
    for (std::uint32_t f : indices) frame_list += (frame_list.empty() ? "" : ", ") + std::to_string(f);
    const char* quality = options.embree_quality == RTC_BUILD_QUALITY_LOW ? "low"
                          : options.embree_quality == RTC_BUILD_QUALITY_MEDIUM ? "medium" : "refit";
    std::printf("{\"scene\": \"%s\", \"side\": \"%s\", \"embree_build\": \"%s\", \"self\": %s, \"triangles\": %zu, "
                "\"frames\": [%s], \"run\": %s, \"digest\": \"%016llx\"}\n",
                scene_name.c_str(), options.only.c_str(), quality, self ? "true" : "false", triangles, frame_list.c_str(),
                side.c_str(), static_cast<unsigned long long>(pairs_digest(pairs)));
    return 0;
}

int run(const Options& options) {
    if (options.check_rule > 0) return check_rule(options.check_rule);
    const Scene scene = options.inputs.empty() ? make_builtin_scene(options.scene) : open_inputs(options.inputs);
    const std::string scene_name = options.inputs.empty() ? options.scene : scene.name;
    const bool self = options.self == "scene" ? scene.self_collision : options.self == "on";
    const std::uint32_t count = scene.source->frame_count();
    std::vector<std::uint32_t> indices = options.frames.empty() ? spread_frames(count, 5) : options.frames;
    if (options.every_frame) {
        indices.resize(count);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    std::vector<Frame> frames;
    std::size_t triangles = 0;
    for (std::uint32_t f : indices) frames.push_back(scene.source->frame(f));
    for (const ObjectFrame& o : frames.front().objects) triangles += o.triangle_count();

    if (!options.only.empty()) return run_one_side(options, scene_name, self, indices, frames, triangles);

    std::vector<PairSet> exact;
    std::vector<OursRun> ours;
    for (int threads : options.threads) {
        std::vector<PairSet> pairs;
        ours.push_back(run_ours(frames, self, threads, pairs));
        if (exact.empty()) exact = std::move(pairs);
        else if (pairs != exact) std::cerr << "warning: aabb's pairs differ between thread counts\n";
    }
    const int peer_threads = *std::max_element(options.threads.begin(), options.threads.end());
    const PeerRun peer = run_peer(frames, self, exact, options.embree_quality, peer_threads);
    const AdjacentSplit split = options.split ? split_adjacent(frames, self) : AdjacentSplit{};
    const bool has_objects = frames.front().objects.size() > 1;
    std::string fcl = "null";
    if (options.fcl && has_objects) {
        const std::size_t fcl_count = options.fcl_frames > 0 ? std::min(options.fcl_frames, frames.size()) : frames.size();
        const FclRun r = run_fcl(frames, exact, fcl_count, peer_threads);
        char text[256];
        std::snprintf(text, sizeof text, "{\"frames\": %zu, \"ms\": %.3f, \"pairs\": %.0f, \"extra\": %zu, \"missed\": %zu}",
                      r.frames, r.total_ms, r.pairs, r.extra, r.missed);
        fcl = text;
    }

    std::string frame_list;
    for (std::uint32_t f : indices) frame_list += (frame_list.empty() ? "" : ", ") + std::to_string(f);
    std::string ours_json;
    for (const OursRun& r : ours) ours_json += (ours_json.empty() ? "" : ", ") + json_ours(r);
    const char* quality = options.embree_quality == RTC_BUILD_QUALITY_LOW ? "low"
                          : options.embree_quality == RTC_BUILD_QUALITY_MEDIUM ? "medium" : "refit";
    std::printf("{\"scene\": \"%s\", \"embree_build\": \"%s\", \"self\": %s, \"triangles\": %zu, \"frames\": [%s], \"aabb\": [%s], "
                "\"peer\": {\"ms\": %.3f, \"refit_ms\": %.3f, \"collide_ms\": %.3f, \"narrow_ms\": %.3f, "
                "\"embree_candidates\": %.0f, \"colliding\": %.0f, \"extra\": %zu, \"missed\": %zu, \"repeated\": %zu}, \"fcl\": %s, "
                "\"narrow_split\": {\"adjacent\": %zu, \"other\": %zu, \"engine_adjacent_ms\": %.3f, "
                "\"engine_other_ms\": %.3f, \"cgal_adjacent_ms\": %.3f, \"cgal_other_ms\": %.3f}}\n",
                scene_name.c_str(), quality, self ? "true" : "false", triangles, frame_list.c_str(), ours_json.c_str(),
                peer.total_ms, peer.refit_ms, peer.collide_ms, peer.narrow_ms, peer.candidates, peer.colliding,
                peer.extra, peer.missed, peer.repeated, fcl.c_str(), split.adjacent, split.other,
                split.engine_adjacent_ms, split.engine_other_ms, split.cgal_adjacent_ms, split.cgal_other_ms);
    return peer.extra + peer.missed + peer.repeated == 0 ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
    keep_freed_memory();  // as the collidescope command does, for both sides of the comparison
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& error) {
        std::cerr << "bench_embree_cgal_peers: " << error.what() << "\n";
        return 1;
    }
}
