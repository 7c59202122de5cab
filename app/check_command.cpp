// `collidescope check`: runs a scene's frames through a method and reports the colliding
// triangle pairs (summary on stderr, --pairs TSV, --stats JSON Lines, exit code).

#include "check_between.hpp"
#include "check_regions.hpp"
#include "check_sinks.hpp"
#include "commands.hpp"
#include "engine_cli_options.hpp"
#include "frame_range.hpp"
#include "interrupt.hpp"
#include "output_stream.hpp"
#include "progress.hpp"
#include "ranks/ranks.hpp"
#include "scene_input.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/scene.hpp"

#include <chrono>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <optional>

namespace collidescope::app {
namespace {

struct CheckOptions {
    std::vector<std::string> inputs;
    std::string scene;            ///< built-in scene NAME[:PRESET], instead of inputs
    std::string frames;           ///< "" = every frame
    std::string pairs;            ///< TSV output ("" = none, "-" = stdout)
    std::string stats;            ///< JSON Lines output ("" = none, "-" = stdout)
    std::string regions;          ///< regions as JSON Lines ("" = none, "-" = stdout)
    bool exit_zero = false;
    bool quiet = false;
    bool between_frames = false;  ///< continuous detection over each interval instead of frames
    double ccd_tolerance = 0;     ///< --ccd-tolerance (0: automatic)
    EngineOptions engine;           ///< --method, --self, --threads, --gpu-*, --aabb-*
};

constexpr const char* k_check_footer = R"(Frames (--frames) are numbered from 0 in scene order and the range is half-open:
  A:B = frames A..B-1, A: = from A to the end, :B = frames 0..B-1, N = frame N alone.
  An empty range or one past the last frame is an error.
Outputs (FILE may be - for stdout; logs and progress always go to stderr):
  --pairs  one line per colliding pair: frame<TAB>objA<TAB>triA<TAB>objB<TAB>triB, objects
           numbered from 0 in input order, triangles from 0 in file order, each pair once
           with (objA,triA) < (objB,triB), lines sorted numerically.
  --stats  JSON Lines, one object per frame: {"frame", "method", "ms": {...}, "counts": {...}}.
  --regions  JSON Lines, one object per interpenetration region per frame: {"frame", "region"
           (an id that follows the region over frames), "objects", "names", "pairs", "triangles",
           "loops", "curve_length", "coplanar_area", "inside_area" ([a's inside b, b's inside a]),
           "depth" (null where not defined), "box", "predecessors", "curves": [{"closed",
           "length", "points"}]}; then a line per region on stderr (docs/explanation/regions.md).
With --between-frames, each interval from frame k to k + 1 instead (vertices moving on straight
  lines; same meshes at both ends): a pair is reported when its triangles touch at some time
  in it, within --ccd-tolerance (docs/explanation/between-frames.md). --pairs adds two columns:
  k objA triA objB triB toi pass, toi a lower bound of the first contact in [0, 1] and pass 1
  when the pair is apart at both frames (a pass-through). --stats: one object per interval.
  A file output is written as FILE.partial, flushed after every frame, and renamed to FILE
  when the run completes: an interrupted run leaves only FILE.partial.
SIGINT or SIGTERM stops after the current frame (a second one at once) and says how many
frames were written.
Exit codes: 0 no collisions, 1 collisions found, 2 error (bad input or usage),
  130 stopped by SIGINT, 143 stopped by SIGTERM.)";

std::string scene_line(const Scene& scene, const FrameRange& range, const PipelineConfig& config) {
    std::string line = "scene '" + scene.name + "'";
    if (!scene.preset.empty()) line += " (" + scene.preset + ")";
    line += ": " + std::to_string(scene.source->object_count()) + " objects, frames " +
            std::to_string(range.begin) + ".." + std::to_string(range.end - 1) + " of " +
            std::to_string(scene.source->frame_count()) + ", method " + config.method +
            ", self-collision " + (config.self_collision ? "on" : "off");
    return line;
}

// Where an output's data is: under mpirun the run's output (rank 0 assembles it there from every
// rank's file, ranks.hpp), not this rank's temporary file.
std::string location(const OutputStream& output, const std::string& target) {
    if (!ranks::parallel()) return output.location();
    return target == "-" ? "stdout" : OutputStream::partial_name(target);
}

// The total line: serially this run's; under mpirun rank 0 prints one for the run when every
// rank is done, the sums of the ranks' totals in the form of a serial run's line, then the
// number of ranks and the wall time since rank 0's `start`.
void log_total_line(Progress& progress, const SummaryPrinter& summary, std::chrono::steady_clock::time_point start) {
    if (!ranks::parallel()) {
        progress.log(summary.total_line());
        return;
    }
    std::vector<double> totals = summary.totals();
    totals.push_back(1);  // summed: the number of ranks
    ranks::summary_line(std::move(totals), [start](const std::vector<double>& sums) {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        char tail[96];
        std::snprintf(tail, sizeof tail, "; %.0f ranks, %.3f s wall time", sums.back(), wall);
        return SummaryPrinter::total_line(sums) + tail;
    });
}

// "interrupted by SIGINT after 12 of 60 frames (frames 0..11); partial outputs: pairs.tsv.partial".
std::string interrupted_line(int signal, const FrameRange& range, std::uint32_t end,
                             std::initializer_list<std::string> outputs) {
    std::string line = "interrupted by " + signal_name(signal) + " after " + std::to_string(end - range.begin) + " of " +
                       std::to_string(range.end - range.begin) + " frames (frames " + std::to_string(range.begin) +
                       ".." + std::to_string(end - 1) + ")";
    std::string files;
    for (const std::string& output : outputs) {
        if (!output.empty()) files += (files.empty() ? "" : ", ") + output;
    }
    if (!files.empty()) line += "; partial output: " + files;
    return line;
}

// A line per region over the run, the first k_region_lines of them (all are in the file).
void log_region_lines(Progress& progress, const RegionsWriter& writer, bool quiet, const std::string& where) {
    constexpr std::size_t k_region_lines = 20;
    const std::vector<std::string> lines = writer.summary_lines();
    for (std::size_t i = 0; i < lines.size() && i < k_region_lines && !quiet; ++i) progress.log(lines[i]);
    if (lines.size() > k_region_lines && !quiet) {
        progress.log("... and " + std::to_string(lines.size() - k_region_lines) + " more regions (every one in " +
                     where + ")");
    }
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.3f", writer.ms());
    progress.log(std::to_string(lines.size()) + " regions over the run (found and followed in " + ms + " ms)");
}

int run_check(const CheckOptions& options) {
    if (options.between_frames) {
        if (!options.regions.empty()) throw InputError("--regions and --between-frames: regions are found per frame; run them apart");
        return run_check_between({options.inputs, options.scene, options.frames, options.pairs, options.stats,
                                  options.ccd_tolerance, options.exit_zero, options.quiet, options.engine});
    }
    if ((options.pairs == "-") + (options.stats == "-") + (options.regions == "-") > 1) {
        throw InputError("--pairs, --stats and --regions: only one of them can write to stdout (-)");
    }
    if (!options.regions.empty() && ranks::parallel()) {
        throw InputError("--regions follows regions from frame to frame, so it runs in one process: run it without mpirun");
    }
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = open_scene(options.inputs, options.scene, options.engine.animation);
    // Under mpirun: this rank's block, and outputs of its own that rank 0 assembles (ranks.hpp).
    const FrameRange range = ranks::block(parse_frame_range(options.frames, scene.source->frame_count()));
    const PipelineConfig config = pipeline_config(options.engine, scene);
    Pipeline pipeline(config);

    Progress progress(range.end - range.begin);
    SummaryPrinter summary(progress, options.quiet);
    pipeline.add_sink(summary);
    std::optional<OutputStream> pairs_out;
    std::optional<OutputStream> stats_out;
    std::optional<PairsWriter> pairs_writer;
    std::optional<StatsWriter> stats_writer;
    std::optional<OutputStream> regions_out;
    std::optional<RegionsWriter> regions_writer;
    if (!options.pairs.empty()) {
        pipeline.add_sink(pairs_writer.emplace(pairs_out.emplace(ranks::text_output(options.pairs)).stream()));
    }
    if (!options.stats.empty()) {
        pipeline.add_sink(stats_writer.emplace(stats_out.emplace(ranks::text_output(options.stats)).stream()));
    }
    if (!options.regions.empty()) {
        std::vector<std::string> names;
        for (std::uint32_t i = 0; i < scene.source->object_count(); ++i) names.push_back(scene.source->object_name(i));
        pipeline.add_sink(regions_writer.emplace(regions_out.emplace(options.regions).stream(), std::move(names)));
    }

    // The first frame is read (and validated) before anything is printed, so bad input in a
    // static mesh gives one line on stderr: the error.
    Frame frame = scene.source->frame(ranks::at_frame(range.begin));
    if (!options.quiet) progress.log(scene_line(scene, range, config));
    const InterruptGuard interrupt;
    std::uint32_t f = range.begin;
    for (;;) {
        pipeline.process(frame);
        // Every finished frame reaches the disk: a killed run keeps it in the .partial file.
        if (pairs_out) pairs_out->end_frame(f);
        if (stats_out) stats_out->end_frame(f);
        if (regions_out) regions_out->end_frame(f);
        progress.advance();
        if (++f == range.end || interrupt.signal() != 0) break;
        frame = scene.source->frame(ranks::at_frame(f));
    }
    progress.finish();
    if (interrupt.signal() != 0) {
        if (pairs_out) pairs_out->finish_partial();
        if (stats_out) stats_out->finish_partial();
        if (regions_out) regions_out->finish_partial();
        log_total_line(progress, summary, start);
        progress.log(interrupted_line(interrupt.signal(), range, f,
                                      {pairs_out ? location(*pairs_out, options.pairs) : std::string(),
                                       stats_out ? location(*stats_out, options.stats) : std::string(),
                                       regions_out ? regions_out->location() : std::string()}));
        return interrupted_exit_code(interrupt.signal());
    }
    if (pairs_out) pairs_out->finish();
    if (stats_out) stats_out->finish();
    if (regions_out) regions_out->finish();
    if (regions_writer) log_region_lines(progress, *regions_writer, options.quiet, regions_out->location());
    log_total_line(progress, summary, start);
    return summary.colliding_pairs() > 0 && !options.exit_zero ? 1 : 0;
}

}  // namespace

Command add_check_command(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* check = app.add_subcommand(
        "check", "Find the colliding triangle pairs of every frame; exit 1 when there are any");
    check->footer(k_check_footer);
    check->add_option("inputs", options->inputs,
                      "Mesh files (static over all frames), frame patterns (cloth.%04d.ply, "
                      "cloth.####.obj), meshes with a point cache (body.obj@body.pc2, .pc2 or .mdd) "
                      "or scene.json manifests; one object per mesh or pattern")
        ->type_name("INPUT");
    check->add_option("--scene", options->scene,
                      "A built-in scene instead of INPUT files: NAME[:PRESET] (" +
                          builtin_scene_list() + ")")
        ->type_name("NAME[:PRESET]");
    check->add_option("--frames", options->frames, "Frames to check: A:B (half-open), A:, :B or N")
        ->type_name("A:B");
    check->add_option("--pairs", options->pairs, "Write the colliding pairs as TSV (- = stdout)")
        ->type_name("FILE");
    check->add_option("--stats", options->stats, "Write per-frame stats as JSON Lines (- = stdout)")
        ->type_name("FILE");
    check->add_option("--regions", options->regions,
                      "Write the interpenetration regions (curves, ids over frames) as JSON Lines (- = stdout)")
        ->type_name("FILE");
    CLI::Option* between = check->add_flag("--between-frames", options->between_frames,
                    "Continuous detection between consecutive frames (linear motion): pairs that touch at any "
                    "time in an interval, pass-throughs included");
    check->add_option("--ccd-tolerance", options->ccd_tolerance,
                      "With --between-frames: a reported pair comes within this distance of touching (0: 1e-6 of "
                      "each interval's extent)")
        ->needs(between)
        ->type_name("D");
    check->add_flag("--exit-zero", options->exit_zero, "Exit 0 even when collisions are found");
    check->add_flag("-q,--quiet", options->quiet, "Only the total line on stderr, no per-frame lines");
    add_engine_options(*check, options->engine);
    return {check, [options] { return run_check(*options); }};
}

}  // namespace collidescope::app
