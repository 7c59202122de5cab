// Between-frames (continuous) detection against the CCD peer built the way the literature's
// CPU codes are (issue 39, point 4; peers/ccd_peer.hpp): Embree swept-box refit + rtcCollide,
// then cubic root finding per vertex-face and edge-edge query (peers/ccd_root_finding.hpp).
//
//   build-peer/bench/bench_ccd_peers --scene NAME[:PRESET] --method ours|peer [--threads 2]
//       [--self | --no-self] [--frames N | A:B | A:] [--pairs FILE] [--peer-build low|refit]
//
// Runs one side over every interval k -> k+1 of the scene's first N frames, or of frames A..B-1
// (half-open, as `collidescope check --frames A:B`; all frames without --frames), timing only
// the detection: ours BetweenFrames::detect (its swept trees are kept and refit between
// intervals), the peer's refit + collide + narrow phase (its Embree scenes
// likewise). Both sides time their first interval too, which builds their trees. Both run
// under a tbb::global_control of T threads (as `collidescope check --between-frames
// --threads T`); the peer's Embree device gets `threads=T` besides (as the per-frame peer).
// Self-collision follows the scene, as `collidescope check --scene` decides it, unless
// --self or --no-self says. Prints one JSON line: scene, method, threads, intervals, total_ms
// (sum over the intervals), pairs and pass_throughs (sums), candidates, stage split and a
// digest of every interval's sorted pairs. --pairs writes the contacts (binary, below).
//
//   build-peer/bench/bench_ccd_peers --compare OURS PEER --scene NAME [the same options]
//
// Compares two --pairs files interval by interval: pairs the peer missed and extra pairs,
// pass-through and toi disagreements on the common pairs, and a diagnosis of the differences
// (exact static test and the features' distance at 257 sample times of the interval).
//
// Built only when Embree 3 is installed (bench/CMakeLists.txt).

#include "peers/ccd_peer.hpp"
#include "peers/ccd_root_finding.hpp"

#include "ccd/interval_checks.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/datasets.hpp"
#include "collidescope/geometry.hpp"
#include "collidescope/memory.hpp"
#include "collidescope/scene.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace collidescope;
using namespace collidescope::peers;

struct Options {
    std::string scene;
    std::vector<std::string> inputs;  // non-empty: these inputs instead of a built-in scene
    std::string method;               // ours or peer
    int threads = 2;
    std::optional<bool> self;         // unset: the scene's setting
    std::uint32_t first = 0;          // the first frame used
    std::uint32_t frames = 0;         // the end of the range (exclusive); 0: the scene's end
    std::string pairs_file;
    std::string compare_ours, compare_peer;
    bool peer_rebuild = true;  // --peer-build low (default) or refit
};

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--scene") options.scene = value();
        else if (arg == "--method") options.method = value();
        else if (arg == "--threads") options.threads = std::stoi(value());
        else if (arg == "--self") options.self = true;
        else if (arg == "--no-self") options.self = false;
        else if (arg == "--frames") {
            const std::string range = value();
            const std::size_t colon = range.find(':');
            if (colon == std::string::npos) {
                options.frames = static_cast<std::uint32_t>(std::stoul(range));
            } else {
                options.first = static_cast<std::uint32_t>(std::stoul(range.substr(0, colon)));
                if (colon + 1 < range.size()) options.frames = static_cast<std::uint32_t>(std::stoul(range.substr(colon + 1)));
            }
        }
        else if (arg == "--pairs") options.pairs_file = value();
        else if (arg == "--peer-build") {
            const std::string build = value();
            if (build != "low" && build != "refit") throw std::invalid_argument("--peer-build low|refit");
            options.peer_rebuild = build == "low";
        }
        else if (arg == "--compare") {
            options.compare_ours = value();
            options.compare_peer = value();
        } else if (!arg.starts_with("--")) options.inputs.push_back(arg);
        else throw std::invalid_argument("unknown argument " + arg);
    }
    if (options.compare_ours.empty() && options.method != "ours" && options.method != "peer")
        throw std::invalid_argument("--method ours|peer (or --compare OURS PEER)");
    if (options.threads < 1) throw std::invalid_argument("--threads: at least 1");
    if (options.scene.empty() == options.inputs.empty()) throw std::invalid_argument("give --scene NAME or INPUT files");
    return options;
}

// ---- the scene's intervals -------------------------------------------------------------

struct SceneRun {
    Scene scene;
    std::string name;
    bool self = false;
    std::uint32_t first = 0;   // frames used: first .. frames - 1, intervals frames - first - 1
    std::uint32_t frames = 0;
};

SceneRun open(const Options& options) {
    SceneRun run{options.inputs.empty() ? make_builtin_scene(options.scene) : open_inputs(options.inputs)};
    run.name = options.inputs.empty() ? options.scene : run.scene.name;
    run.self = options.self.value_or(run.scene.self_collision);
    const std::uint32_t count = run.scene.source->frame_count();
    run.first = options.first;
    run.frames = options.frames > 0 ? std::min(options.frames, count) : count;
    if (run.frames < run.first + 2) throw std::invalid_argument("the range needs at least two frames");
    return run;
}

// Calls visit(from, to) for every interval, reading each frame once.
template <typename Visit>
void for_each_interval(SceneRun& run, Visit&& visit) {
    Frame from = run.scene.source->frame(run.first);
    for (std::uint32_t f = run.first; f + 1 < run.frames; ++f) {
        Frame to = run.scene.source->frame(f + 1);
        visit(from, to);
        from = std::move(to);
    }
}

// ---- the pairs file: per interval {u32 from, u32 count}, then count records ----------------

struct Record {
    std::uint32_t obj_a, tri_a, obj_b, tri_b;
    double toi;
    std::uint32_t pass_through, unused;
};
static_assert(sizeof(Record) == 32);

class PairsWriter {
public:
    explicit PairsWriter(const std::string& path) : m_file(path.empty() ? nullptr : std::fopen(path.c_str(), "wb")) {
        if (!path.empty() && m_file == nullptr) throw std::runtime_error("cannot write " + path);
    }
    ~PairsWriter() {
        if (m_file != nullptr) std::fclose(m_file);
    }
    PairsWriter(const PairsWriter&) = delete;
    PairsWriter& operator=(const PairsWriter&) = delete;

    void write(std::uint32_t from, const std::vector<IntervalContact>& contacts) {
        if (m_file == nullptr) return;
        const std::uint32_t header[2] = {from, static_cast<std::uint32_t>(contacts.size())};
        std::vector<Record> records;
        records.reserve(contacts.size());
        for (const IntervalContact& c : contacts) {
            records.push_back({c.pair.obj_a, c.pair.tri_a, c.pair.obj_b, c.pair.tri_b, c.toi, c.pass_through ? 1u : 0u, 0});
        }
        if (std::fwrite(header, sizeof header, 1, m_file) != 1 ||
            std::fwrite(records.data(), sizeof(Record), records.size(), m_file) != records.size())
            throw std::runtime_error("writing the pairs failed");
    }

private:
    std::FILE* m_file;
};

// One interval's records from a pairs file; false at its end.
bool read_interval(std::FILE* file, std::uint32_t& from, std::vector<Record>& records) {
    std::uint32_t header[2];
    if (std::fread(header, sizeof header, 1, file) != 1) return false;
    from = header[0];
    records.resize(header[1]);
    if (std::fread(records.data(), sizeof(Record), records.size(), file) != records.size())
        throw std::runtime_error("a pairs file ends inside an interval");
    return true;
}

// ---- one side, timed --------------------------------------------------------------------

struct Digest {  // FNV-1a over every interval's sorted pairs
    std::uint64_t hash = 1469598103934665603ull;
    void mix(std::uint64_t value) {
        for (int byte = 0; byte < 8; ++byte) {
            hash ^= (value >> (8 * byte)) & 0xFF;
            hash *= 1099511628211ull;
        }
    }
    void add(const std::vector<IntervalContact>& contacts) {
        mix(contacts.size());
        for (const IntervalContact& c : contacts) {
            mix((std::uint64_t{c.pair.obj_a} << 32) | c.pair.tri_a);
            mix((std::uint64_t{c.pair.obj_b} << 32) | c.pair.tri_b);
        }
    }
};

struct SideTotals {
    std::uint32_t intervals = 0;
    double total_ms = 0, broad_ms = 0, narrow_ms = 0, collide_ms = 0;  // broad: refit (peer), swept trees (ours)
    std::uint64_t pairs = 0, pass_throughs = 0, candidates = 0, unresolved = 0;
    Digest digest;

    void add(const std::vector<IntervalContact>& contacts) {
        ++intervals;
        pairs += contacts.size();
        for (const IntervalContact& c : contacts) {
            pass_throughs += c.pass_through;
            unresolved += !c.resolved;
        }
        digest.add(contacts);
    }
};

SideTotals run_ours(SceneRun& run, PairsWriter& writer) {
    BetweenFramesOptions options;
    options.self_collision = run.self;
    BetweenFrames detector(options);
    SideTotals totals;
    for_each_interval(run, [&](const Frame& from, const Frame& to) {
        const Clock::time_point start = Clock::now();
        const IntervalResult result = detector.detect(from, to);
        totals.total_ms += ms_since(start);
        totals.broad_ms += result.stats.broad_ms;
        totals.narrow_ms += result.stats.narrow_ms;
        totals.candidates += result.stats.candidate_pairs;
        totals.add(result.contacts);
        writer.write(from.index, result.contacts);
    });
    return totals;
}

SideTotals run_peer(SceneRun& run, int threads, bool rebuild, PairsWriter& writer) {
    CcdPeer peer(run.self, threads, rebuild);
    SideTotals totals;
    for_each_interval(run, [&](const Frame& from, const Frame& to) {
        CcdPeerStats stats;
        const Clock::time_point start = Clock::now();
        const std::vector<IntervalContact> contacts = peer.detect(from, to, stats);
        totals.total_ms += ms_since(start);
        totals.broad_ms += stats.refit_ms;
        totals.collide_ms += stats.collide_ms;
        totals.narrow_ms += stats.narrow_ms;
        totals.candidates += stats.candidates;
        totals.add(contacts);
        writer.write(from.index, contacts);
    });
    return totals;
}

int run_side(const Options& options) {
    SceneRun run = open(options);
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(options.threads));
    PairsWriter writer(options.pairs_file);
    const bool ours = options.method == "ours";
    const SideTotals t = ours ? run_ours(run, writer) : run_peer(run, options.threads, options.peer_rebuild, writer);
    std::size_t triangles = 0;
    for (std::uint32_t o = 0; o < run.scene.source->object_count(); ++o) {
        triangles += run.scene.source->frame(run.first).objects[o].triangle_count();
    }
    std::printf("{\"scene\": \"%s\", \"method\": \"%s\", \"self\": %s, \"threads\": %d, \"triangles\": %zu, "
                "\"intervals\": %u, \"total_ms\": %.3f, \"%s\": %.3f, \"collide_ms\": %.3f, \"narrow_ms\": %.3f, "
                "\"candidates\": %llu, \"pairs\": %llu, \"pass_throughs\": %llu, \"unresolved\": %llu, \"digest\": \"%016llx\"}\n",
                run.name.c_str(), options.method.c_str(), run.self ? "true" : "false", options.threads, triangles, t.intervals,
                t.total_ms, ours ? "swept_trees_ms" : options.peer_rebuild ? "rebuild_ms" : "refit_ms", t.broad_ms, t.collide_ms, t.narrow_ms,
                static_cast<unsigned long long>(t.candidates), static_cast<unsigned long long>(t.pairs),
                static_cast<unsigned long long>(t.pass_throughs), static_cast<unsigned long long>(t.unresolved),
                static_cast<unsigned long long>(t.digest.hash));
    return 0;
}

// ---- the comparison ---------------------------------------------------------------------

constexpr int k_samples = 256;           // the diagnosis samples t = k / 256
constexpr std::size_t k_diagnosed = 20000;  // differences diagnosed per kind (the first ones)
constexpr int k_examples = 4;            // printed per kind, on stderr

// A differing pair at the sample times (positions interpolated in doubles): whether the exact
// static test finds it touching at one, and its least distance over them (the distances of
// the features the queries test, minus those the self rule skips; valid while apart).
struct Diagnosis {
    bool touching = false;
    double distance = INFINITY;
};

bool shares(const TriIndices& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

double feature_distance(const std::array<Vec3, 3>& a, const TriIndices& ia, const std::array<Vec3, 3>& b, const TriIndices& ib,
                        bool self) {
    double d = INFINITY;
    for (int i = 0; i < 3; ++i) {
        if (!(self && shares(ib, ia[i]))) d = std::min(d, point_triangle_distance(a[i], b[0], b[1], b[2]));
        if (!(self && shares(ia, ib[i]))) d = std::min(d, point_triangle_distance(b[i], a[0], a[1], a[2]));
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, j1 = (j + 1) % 3;
            if (self && (ia[i] == ib[j] || ia[i] == ib[j1] || ia[i1] == ib[j] || ia[i1] == ib[j1])) continue;
            d = std::min(d, segment_segment_distance(a[i], a[i1], b[j], b[j1]));
        }
    }
    return d;
}

// The pair's corners at time t (interpolated in doubles), and its vertex indices.
struct PairAt {
    std::array<Vec3, 3> a, b;
    TriIndices ia, ib;
    bool self;
};

PairAt pair_at(const Frame& from, const Frame& to, const TrianglePair& pair, double t) {
    PairAt p{{}, {}, from.objects[pair.obj_a].topology->triangles[pair.tri_a],
             from.objects[pair.obj_b].topology->triangles[pair.tri_b], pair.obj_a == pair.obj_b};
    for (int i = 0; i < 3; ++i) {
        const Vec3& a0 = from.objects[pair.obj_a].vertices[p.ia[i]];
        const Vec3& b0 = from.objects[pair.obj_b].vertices[p.ib[i]];
        p.a[i] = a0 + t * (to.objects[pair.obj_a].vertices[p.ia[i]] - a0);
        p.b[i] = b0 + t * (to.objects[pair.obj_b].vertices[p.ib[i]] - b0);
    }
    return p;
}

bool touching(const PairAt& p) {
    return p.self ? self_triangles_collide(p.ia, p.a, p.ib, p.b) : triangles_intersect(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
}

// Sampled over [t0, t1] at `samples` + 1 times.
Diagnosis diagnose(const Frame& from, const Frame& to, const TrianglePair& pair, double t0 = 0, double t1 = 1,
                   int samples = k_samples) {
    Diagnosis d;
    for (int k = 0; k <= samples; ++k) {
        const PairAt p = pair_at(from, to, pair, t0 + (t1 - t0) * k / samples);
        d.touching = d.touching || touching(p);
        d.distance = std::min(d.distance, feature_distance(p.a, p.ia, p.b, p.ib, p.self));
    }
    return d;
}

// Common pairs where the peer's toi is earlier than ours by more than 1e-6: whether the exact
// test finds contact in between (at 9 times): that would break ours' lower bound; else the
// peer's root is within δ before the contact (its tolerance band).
struct EarlierToi {
    std::uint64_t count = 0, diagnosed = 0, touching_before_ours = 0;

    void add(const Frame& from, const Frame& to, const Record& ours, const Record& peer) {
        ++count;
        if (diagnosed >= k_diagnosed) return;
        ++diagnosed;
        const TrianglePair pair{ours.obj_a, ours.tri_a, ours.obj_b, ours.tri_b};
        touching_before_ours += diagnose(from, to, pair, peer.toi, ours.toi - 1e-9, 8).touching;
    }

    std::string json() const {
        char text[200];
        std::snprintf(text, sizeof text, "{\"count\": %llu, \"diagnosed\": %llu, \"touching_before_ours_toi\": %llu}",
                      static_cast<unsigned long long>(count), static_cast<unsigned long long>(diagnosed),
                      static_cast<unsigned long long>(touching_before_ours));
        return text;
    }
};

// Common pairs whose toi differ by more than 1e-3 with ours the earlier (ours' toi is a lower
// bound, at which the pair is within δ): the features' distance at ours' toi, and whether the
// exact test finds contact between the two tois (an earlier contact the peer's roots missed).
struct LaterToi {
    std::uint64_t count = 0, diagnosed = 0, ours_within_2_delta = 0, touching_before_peer = 0;

    void add(const Frame& from, const Frame& to, const Record& ours, const Record& peer, double delta) {
        ++count;
        if (diagnosed >= k_diagnosed) return;
        ++diagnosed;
        const TrianglePair pair{ours.obj_a, ours.tri_a, ours.obj_b, ours.tri_b};
        const PairAt at = pair_at(from, to, pair, ours.toi);
        ours_within_2_delta += feature_distance(at.a, at.ia, at.b, at.ib, at.self) <= 2 * delta;
        touching_before_peer += diagnose(from, to, pair, ours.toi, peer.toi - 1e-9, 32).touching;
    }

    std::string json() const {
        char text[240];
        std::snprintf(text, sizeof text, "{\"count\": %llu, \"diagnosed\": %llu, \"ours_within_2_delta_at_its_toi\": %llu, "
                      "\"touching_before_peer_toi\": %llu}", static_cast<unsigned long long>(count),
                      static_cast<unsigned long long>(diagnosed), static_cast<unsigned long long>(ours_within_2_delta),
                      static_cast<unsigned long long>(touching_before_peer));
        return text;
    }
};

// All twelve positions (both triangles at both ends) in one plane, exactly.
bool coplanar_motion(const Frame& from, const Frame& to, const TrianglePair& pair) {
    std::vector<Vec3> points;
    for (const Frame* frame : {&from, &to}) {
        for (std::uint32_t k = 0; k < 2; ++k) {
            const std::array<Vec3, 3> c = frame->objects[k == 0 ? pair.obj_a : pair.obj_b].corners(k == 0 ? pair.tri_a : pair.tri_b);
            points.insert(points.end(), c.begin(), c.end());
        }
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            bool plane = false;
            for (int drop = 0; drop < 3 && !plane; ++drop) plane = orient2d(points[0], points[i], points[j], drop) != 0;
            if (!plane) continue;
            for (const Vec3& p : points)
                if (orient3d(points[0], points[i], points[j], p) != 0) return false;
            return true;
        }
    }
    return true;  // on a line
}

// The pairs one side reported and the other did not, diagnosed (the first k_diagnosed);
// toi0: of them, reported at toi 0 by that side.
struct Differences {
    const char* kind;
    std::uint64_t count = 0, diagnosed = 0, touching = 0, near = 0, coplanar = 0, shared = 0, start = 0;
    int examples = 0;

    void add(const Frame& from, const Frame& to, const Record& r, double delta) {
        ++count;
        const TrianglePair pair{r.obj_a, r.tri_a, r.obj_b, r.tri_b};
        start += r.toi == 0;
        if (diagnosed >= k_diagnosed) return;
        ++diagnosed;
        const Diagnosis d = diagnose(from, to, pair);
        const bool flat = coplanar_motion(from, to, pair);
        touching += d.touching;
        near += !d.touching && d.distance <= 100 * delta;
        coplanar += flat;
        const auto& triangles = from.objects[pair.obj_a].topology->triangles;
        const bool adjacent = pair.obj_a == pair.obj_b &&
                              (shares(triangles[pair.tri_b], triangles[pair.tri_a][0]) || shares(triangles[pair.tri_b], triangles[pair.tri_a][1]) ||
                               shares(triangles[pair.tri_b], triangles[pair.tri_a][2]));
        shared += adjacent;
        if (examples++ < k_examples) {
            std::fprintf(stderr, "%s: interval %u: (%u,%u)-(%u,%u) toi %.9f%s, touching at a sample: %s, least sampled distance %.3g delta%s%s\n",
                         kind, from.index, r.obj_a, r.tri_a, r.obj_b, r.tri_b, r.toi, r.pass_through ? " pass-through" : "",
                         d.touching ? "yes" : "no", d.distance / delta, flat ? ", coplanar motion" : "", adjacent ? ", shares a vertex" : "");
        }
    }

    std::string json() const {
        char text[400];
        std::snprintf(text, sizeof text,
                      "{\"count\": %llu, \"toi0\": %llu, \"diagnosed\": %llu, \"touching_at_a_sample\": %llu, "
                      "\"within_100_delta_at_a_sample\": %llu, \"coplanar_motion\": %llu, \"self_sharing_a_vertex\": %llu}",
                      static_cast<unsigned long long>(count), static_cast<unsigned long long>(start),
                      static_cast<unsigned long long>(diagnosed), static_cast<unsigned long long>(touching),
                      static_cast<unsigned long long>(near), static_cast<unsigned long long>(coplanar),
                      static_cast<unsigned long long>(shared));
        return text;
    }
};

std::FILE* open_for_reading(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) throw std::runtime_error("cannot read " + path);
    return file;
}

int run_compare(const Options& options) {
    SceneRun run = open(options);
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> ours_file(open_for_reading(options.compare_ours), &std::fclose);
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> peer_file(open_for_reading(options.compare_peer), &std::fclose);
    Differences missed{"missed"}, extra{"extra"};  // of the peer, against ours
    LaterToi later;      // the peer's toi against ours
    EarlierToi earlier;
    std::uint64_t ours_pairs = 0, peer_pairs = 0, common = 0, pass_differ = 0;
    double toi_max_diff = 0;
    std::uint32_t intervals = 0;
    std::vector<Record> ours, peer;
    for_each_interval(run, [&](const Frame& from, const Frame& to) {
        std::uint32_t ours_from = 0, peer_from = 0;
        if (!read_interval(ours_file.get(), ours_from, ours) || !read_interval(peer_file.get(), peer_from, peer)) return;
        if (ours_from != from.index || peer_from != from.index) throw std::runtime_error("the pairs files are of other intervals");
        ++intervals;
        ours_pairs += ours.size();
        peer_pairs += peer.size();
        const double delta = ccd::interval_tolerance(from, to, 0);
        const auto key = [](const Record& r) { return TrianglePair{r.obj_a, r.tri_a, r.obj_b, r.tri_b}; };
        std::size_t i = 0, j = 0;
        while (i < ours.size() || j < peer.size()) {
            if (j == peer.size() || (i < ours.size() && key(ours[i]) < key(peer[j]))) {
                missed.add(from, to, ours[i++], delta);
            } else if (i == ours.size() || key(peer[j]) < key(ours[i])) {
                extra.add(from, to, peer[j++], delta);
            } else {
                ++common;
                pass_differ += ours[i].pass_through != peer[j].pass_through;
                const double diff = peer[j].toi - ours[i].toi;
                toi_max_diff = std::max(toi_max_diff, std::abs(diff));
                if (diff > 1e-3) later.add(from, to, ours[i], peer[j], delta);
                if (diff < -1e-6) earlier.add(from, to, ours[i], peer[j]);
                ++i;
                ++j;
            }
        }
    });
    std::printf("{\"scene\": \"%s\", \"self\": %s, \"intervals\": %u, \"ours_pairs\": %llu, \"peer_pairs\": %llu, \"common\": %llu, "
                "\"missed\": %s, \"extra\": %s, \"pass_through_differ\": %llu, \"peer_toi_later_1e-3\": %s, "
                "\"peer_toi_earlier_1e-6\": %s, \"toi_max_diff\": %.3g}\n",
                run.name.c_str(), run.self ? "true" : "false", intervals, static_cast<unsigned long long>(ours_pairs),
                static_cast<unsigned long long>(peer_pairs), static_cast<unsigned long long>(common), missed.json().c_str(),
                extra.json().c_str(), static_cast<unsigned long long>(pass_differ), later.json().c_str(),
                earlier.json().c_str(), toi_max_diff);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    keep_freed_memory();  // as the collidescope command does, for both sides
    try {
        const Options options = parse(argc, argv);
        return options.compare_ours.empty() ? run_side(options) : run_compare(options);
    } catch (const std::exception& error) {
        std::cerr << "bench_ccd_peers: " << error.what() << "\n";
        return 1;
    }
}
