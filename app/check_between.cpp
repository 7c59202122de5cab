// `check --between-frames`: the frames' range read two at a time, each interval through
// BetweenFrames, the pairs and stats written as each interval finishes.

#include "check_between.hpp"

#include "frame_range.hpp"
#include "interrupt.hpp"
#include "output_stream.hpp"
#include "progress.hpp"
#include "ranks/ranks.hpp"
#include "scene_input.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <thread>

namespace collidescope::app {

double printed_toi(double toi, double unit) { return std::max(0.0, toi - 0.6 * unit); }

namespace {

void write_pairs(std::ostream& out, std::uint32_t frame, const IntervalResult& result) {
    char line[160];
    for (const IntervalContact& c : result.contacts) {
        std::snprintf(line, sizeof line, "%u\t%u\t%u\t%u\t%u\t%.9f\t%d\n", frame, c.pair.obj_a, c.pair.tri_a, c.pair.obj_b,
                      c.pair.tri_b, printed_toi(c.toi, 1e-9), c.pass_through ? 1 : 0);
        out << line;
    }
}

void write_stats(std::ostream& out, std::uint32_t frame, const IntervalResult& result) {
    const IntervalStats& s = result.stats;
    char line[640];
    std::snprintf(line, sizeof line,
                  "{\"interval\":[%u,%u],\"method\":\"between-frames\",\"tolerance\":%.9g,"
                  "\"ms\":{\"broad\":%.6f,\"narrow\":%.6f,\"total\":%.6f},"
                  "\"counts\":{\"candidate_pairs\":%llu,\"start_contacts\":%llu,\"primitive_queries\":%llu,"
                  "\"inclusion_boxes\":%llu,\"contacts\":%llu,\"pass_throughs\":%llu,\"unresolved\":%llu}}\n",
                  frame, frame + 1, s.tolerance, s.broad_ms, s.narrow_ms, s.ms,
                  static_cast<unsigned long long>(s.candidate_pairs), static_cast<unsigned long long>(s.start_contacts),
                  static_cast<unsigned long long>(s.primitive_queries), static_cast<unsigned long long>(s.inclusion_boxes),
                  static_cast<unsigned long long>(s.contacts), static_cast<unsigned long long>(s.pass_throughs),
                  static_cast<unsigned long long>(s.unresolved));
    out << line;
}

struct Totals {
    std::uint64_t intervals = 0, with_contact = 0, pairs = 0, pass_throughs = 0, unresolved = 0;
    double ms = 0, tolerance_min = 0, tolerance_max = 0;

    void add(const IntervalResult& r) {
        const double t = r.stats.tolerance;
        tolerance_min = intervals == 0 ? t : std::min(tolerance_min, t);
        tolerance_max = intervals == 0 ? t : std::max(tolerance_max, t);
        ++intervals;
        with_contact += !r.contacts.empty();
        pairs += r.stats.contacts;
        pass_throughs += r.stats.pass_throughs;
        unresolved += r.stats.unresolved;
        ms += r.stats.ms;
    }
    std::string line() const {
        char tolerance[80];
        if (tolerance_min == tolerance_max) std::snprintf(tolerance, sizeof tolerance, "%.3g", tolerance_min);
        else std::snprintf(tolerance, sizeof tolerance, "%.3g to %.3g", tolerance_min, tolerance_max);
        char text[400];
        std::snprintf(text, sizeof text,
                      "total: %llu intervals, %llu with contact, %llu pairs touching between frames, %llu pass-throughs "
                      "(apart at both frames); tolerance %s; %.3f ms",
                      static_cast<unsigned long long>(intervals), static_cast<unsigned long long>(with_contact),
                      static_cast<unsigned long long>(pairs), static_cast<unsigned long long>(pass_throughs), tolerance, ms);
        std::string out = text;
        if (unresolved > 0) out += "; " + std::to_string(unresolved) + " pairs reported without the tolerance proven (query budget spent)";
        return out;
    }
};

}  // namespace

int run_check_between(const BetweenFramesRun& run) {
    if (run.pairs == "-" && run.stats == "-") throw InputError("--pairs and --stats: only one of them can write to stdout (-)");
    if (ranks::parallel()) {
        throw InputError("--between-frames reads each frame with the next one, so it runs in one process: run it without mpirun");
    }
    if (!(run.tolerance >= 0) || !std::isfinite(run.tolerance)) {
        throw InputError("--ccd-tolerance " + std::to_string(run.tolerance) + ": must be a finite distance >= 0 (0: automatic)");
    }
    const Scene scene = open_scene(run.inputs, run.scene, run.engine.animation);
    const FrameRange range = parse_frame_range(run.frames, scene.source->frame_count());
    if (range.end - range.begin < 2) {
        throw InputError("--between-frames needs at least two frames (the range " + std::to_string(range.begin) + ".." +
                         std::to_string(range.end - 1) + " has one)");
    }
    const PipelineConfig config = pipeline_config(run.engine, scene);
    const int threads = run.engine.threads > 0 ? run.engine.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    std::vector<std::string> names;
    for (std::uint32_t i = 0; i < scene.source->object_count(); ++i) names.push_back(scene.source->object_name(i));
    const std::string label = run.scene.empty() ? (run.inputs.size() == 1 ? run.inputs[0] : "scene '" + scene.name + "'")
                                                : "scene '" + scene.name + "'";

    BetweenFramesOptions options;
    options.tolerance = run.tolerance;
    options.self_collision = config.self_collision;
    BetweenFrames detector(options);
    std::optional<OutputStream> pairs_out, stats_out;
    if (!run.pairs.empty()) pairs_out.emplace(run.pairs);
    if (!run.stats.empty()) stats_out.emplace(run.stats);

    Progress progress(range.end - range.begin - 1);
    Frame from = scene.source->frame(range.begin);
    // The scene line comes after the first interval, so that bad input there (a topology
    // change, a coordinate that is not finite) is the only line printed.
    bool announced = run.quiet;
    const auto announce = [&] {
        if (announced) return;
        announced = true;
        progress.log("scene '" + scene.name + "': " + std::to_string(names.size()) + " objects, intervals between frames " +
                     std::to_string(range.begin) + ".." + std::to_string(range.end - 1) + " (" +
                     std::to_string(range.end - range.begin - 1) + "), linear motion, self-collision " +
                     (config.self_collision ? "on" : "off"));
    };
    const InterruptGuard interrupt;
    Totals totals;
    std::uint32_t f = range.begin;
    for (; f + 1 < range.end && interrupt.signal() == 0; ++f) {
        Frame to = scene.source->frame(f + 1);
        IntervalResult result;
        try {
            result = detector.detect(from, to);
        } catch (const InputError& e) {
            throw InputError(label + ": " + with_object_names(e.what(), names));
        }
        announce();
        totals.add(result);
        if (pairs_out) write_pairs(pairs_out->stream(), f, result);
        if (stats_out) write_stats(stats_out->stream(), f, result);
        if (pairs_out) pairs_out->end_frame(f);
        if (stats_out) stats_out->end_frame(f);
        if (!run.quiet && !result.contacts.empty()) {
            double earliest = 1;
            for (const IntervalContact& c : result.contacts) earliest = std::min(earliest, c.toi);
            char line[200];
            std::snprintf(line, sizeof line, "frames %u-%u: %llu pairs, %llu pass-throughs, first contact at t = %.6f, %.3f ms", f, f + 1,
                          static_cast<unsigned long long>(result.stats.contacts),
                          static_cast<unsigned long long>(result.stats.pass_throughs), printed_toi(earliest, 1e-6), result.stats.ms);
            progress.log(line);
        }
        progress.advance();
        from = std::move(to);
    }
    progress.finish();
    if (interrupt.signal() != 0) {
        if (pairs_out) pairs_out->finish_partial();
        if (stats_out) stats_out->finish_partial();
        progress.log(totals.line());
        progress.log("interrupted by " + signal_name(interrupt.signal()) + " after " + std::to_string(totals.intervals) +
                     " intervals");
        return interrupted_exit_code(interrupt.signal());
    }
    if (pairs_out) pairs_out->finish();
    if (stats_out) stats_out->finish();
    progress.log(totals.line());
    return totals.pairs > 0 && !run.exit_zero ? 1 : 0;
}

}  // namespace collidescope::app
