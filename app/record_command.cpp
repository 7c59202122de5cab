// `collidescope record`: runs a scene's frames through a method and writes the recording
// to one HDF5 file (recorder/, docs/reference/recording.md).

#include "commands.hpp"
#include "number_checks.hpp"
#include "engine_cli_options.hpp"
#include "frame_range.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "ranks/ranks.hpp"
#include "scene_input.hpp"
#include "size_option.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/recorder.hpp"
#include "collidescope/scene.hpp"

#include <charconv>
#include <malloc.h>
#include <memory>

namespace collidescope::app {
namespace {

struct RecordOptions {
    std::vector<std::string> inputs;
    std::string scene;              ///< built-in scene NAME[:PRESET], instead of inputs
    std::string output;             ///< -o, the HDF5 file
    std::string frames;             ///< "" = every frame
    std::string depth = "off";      ///< off | every:N
    std::string budget;             ///< "" = no bound
    std::string queue = "256M";     ///< writer queue memory cap
    int compression = 1;            ///< gzip level of positions, pairs, triangles (0 = none)
    int writer_nice = 10;           ///< nice increment of the writer thread (0 = none)
    std::string join = "virtual";   ///< under mpirun: how the ranks' parts are joined (ranks.hpp)
    bool quiet = false;
    bool regions = false;           ///< --regions: /regions per frame (schema 1.5)
    bool between_frames = false;    ///< --between-frames: /intervals (schema 1.7)
    double ccd_tolerance = 0;       ///< --ccd-tolerance (0: automatic)
    EngineOptions engine;           ///< --method, --self, --threads, --gpu-*, --aabb-*
};

constexpr const char* k_record_footer = R"(Writes one HDF5 file (schema: docs/reference/recording.md; read it with h5py, h5dump,
`collidescope inspect`, `validate`, `compare` or the scripts in scripts/). The file is written
in SWMR mode and flushed after every frame (every group of frames that waited for the writer):
a killed recording keeps every frame flushed before it.
--depth every:N records the GPU cull's depth buffers (one per triangle-level view, read back
after its forward pass) on every frame whose index is a multiple of N, with methods that run
the GPU cull (/gpu/depth: uint16, compressed); the cull's per-pass state, its surviving
triangles and the decision system's inputs are recorded on every frame.
--budget SIZE (e.g. 50M, 2G; K/M/G are powers of 1024) keeps the file near SIZE by dropping
the depth buffers of more and more frames first, then the vertex positions; the summary says
what was dropped.
SIGINT or SIGTERM stops after the current frame (a second one at once): the frames so far are
written, the file is marked partial (attribute `interrupted`) and the run says how many.
A write error (disk full) stops the run with one line naming the file and the frame; the
frames before it stay readable and the file is left unfinished (partial).
Exit codes: 0 recorded (whatever collided), 2 error, 130 stopped by SIGINT, 143 by SIGTERM.)";

// --depth: "off" (0) or "every:N" with N >= 1 (N).
std::uint32_t parse_depth(const std::string& depth) {
    if (depth == "off") return 0;
    const std::string prefix = "every:";
    unsigned every = 0;
    const char* begin = depth.data() + prefix.size();
    const char* end = depth.data() + depth.size();
    const bool ok = depth.rfind(prefix, 0) == 0 && depth.size() > prefix.size() &&
                    std::from_chars(begin, end, every).ptr == end && every >= 1;
    if (!ok) throw InputError("--depth must be 'off' or 'every:N' with N >= 1, not '" + depth + "'");
    return every;
}

recorder::SessionInfo session_info(const Scene& scene, const RecordOptions& options, const PipelineConfig& config,
                                   const FrameRange& range) {
    recorder::SessionInfo info;
    info.scene = scene.name;
    info.preset = scene.preset;
    info.seed = scene.seed;
    info.method = config.method;
    info.self_collision = config.self_collision;
    info.threads = config.threads;
    info.frame_begin = range.begin;
    info.frame_end = range.end;
    info.depth = options.depth;
    info.depth_image_pixels = std::uint64_t(config.gpu.resolution) * std::uint64_t(config.gpu.resolution);
    info.tool_version = COLLIDESCOPE_VERSION;
    info.git_revision = COLLIDESCOPE_GIT_REVISION;
    for (std::uint32_t k = 0; k < scene.source->object_count(); ++k) info.object_names.push_back(scene.source->object_name(k));
    info.frame_times = scene.frame_times;
    info.fps = scene.fps;
    info.clip = scene.clip;
    info.up_axis = scene.up_axis;
    info.regions = options.regions;
    info.between_frames = options.between_frames;
    info.ccd_tolerance = options.ccd_tolerance;
    return info;
}

// "every 4th ... kept at the end" / "none kept at the end".
std::string stride_text(std::uint32_t stride, const char* what) {
    if (stride == 0) return "none kept at the end";
    return "every " + std::to_string(stride) + (stride == 2 ? "nd " : "th ") + what + " kept at the end";
}

std::string summary_line(const recorder::RecordSummary& summary, const std::string& path, std::uint64_t budget,
                         std::uint64_t queue_cap) {
    std::string line = "recorded " + std::to_string(summary.frames) + " frames to " + path + " (" +
                       format_size(summary.file_bytes) + "; writer queue peak " + format_size(summary.queue_peak_bytes) +
                       " of " + format_size(queue_cap) + ")";
    if (summary.depth_frames > 0) line += ", depth images on " + std::to_string(summary.depth_frames) + " frames";
    if (budget == 0) return line;
    line += "; budget " + format_size(budget) + ": ";
    std::vector<std::string> dropped;
    if (summary.depth_dropped > 0) {
        dropped.push_back("the depth images of " + std::to_string(summary.depth_dropped) + " of " +
                          std::to_string(summary.depth_frames) + " frames that had them (" +
                          stride_text(summary.depth_stride, "one") + ")");
    }
    if (summary.positions_dropped > 0) {
        dropped.push_back("the vertex positions of " + std::to_string(summary.positions_dropped) + " of " +
                          std::to_string(summary.frames) + " frames (" +
                          stride_text(summary.positions_stride, "frame") + ")");
    }
    if (dropped.empty()) line += "nothing dropped";
    for (std::size_t i = 0; i < dropped.size(); ++i) line += (i == 0 ? "dropped " : ", then ") + dropped[i];
    if (summary.file_bytes > budget) line += "; still over budget (pairs and stats alone exceed it)";
    return line;
}

int run_record(const RecordOptions& options) {
    // No process-wide mallopt here: the recorder maps its own frame-sized buffers
    // (recorder/src/large_blocks.hpp), which bounds memory without slowing the engine.
    const std::uint32_t depth_every = parse_depth(options.depth);
    if (options.regions && ranks::parallel()) {
        throw InputError("--regions follows regions from frame to frame, so it records in one process: run it without mpirun");
    }
    if (options.between_frames && ranks::parallel()) {
        throw InputError("--between-frames tests each frame with the one before it, so it records in one process: run it "
                         "without mpirun");
    }
    const std::uint64_t budget = options.budget.empty() ? 0 : parse_size(options.budget, "--budget");
    const Scene scene = open_scene(options.inputs, options.scene, options.engine.animation);
    // Under mpirun: this rank's block, into a part file rank 0 joins (ranks.hpp).
    const FrameRange range = ranks::block(parse_frame_range(options.frames, scene.source->frame_count()));
    PipelineConfig config = pipeline_config(options.engine, scene);
    config.gpu.depth_every = depth_every;
    Pipeline pipeline(config);
    Frame frame = scene.source->frame(ranks::at_frame(range.begin));

    recorder::RecorderConfig recorder_config;
    const std::string output = ranks::recording_output(
        options.output, options.join == "copy" ? ranks::RecordingJoin::Copy : ranks::RecordingJoin::Virtual);
    recorder_config.path = output;
    recorder_config.budget_bytes = budget;
    recorder_config.queue_bytes = parse_size(options.queue, "--queue-memory");
    recorder_config.deflate_level = options.compression;
    recorder_config.writer_nice = options.writer_nice;
    recorder::Recorder recorder(recorder_config, session_info(scene, options, config, range), frame);
    pipeline.add_sink(recorder);

    Progress progress(range.end - range.begin);
    if (!options.quiet) {
        progress.log("recording scene '" + scene.name + "': " + std::to_string(scene.source->object_count()) +
                     " objects, frames " + std::to_string(range.begin) + ".." + std::to_string(range.end - 1) +
                     ", method " + config.method + " -> " + output);
    }
    const InterruptGuard interrupt;
    std::uint32_t f = range.begin;
    for (;;) {
        pipeline.process(frame);
        progress.advance();
        if (++f == range.end || interrupt.signal() != 0) break;
        frame = scene.source->frame(ranks::at_frame(f));
    }
    const int signal = interrupt.signal();
    const recorder::RecordSummary summary = recorder.finish(signal != 0 ? signal_name(signal) : std::string());
    progress.finish();
    progress.log(summary_line(summary, output, budget, recorder_config.queue_bytes));
    if (signal == 0) return 0;
    progress.log("interrupted by " + signal_name(signal) + " after " + std::to_string(summary.frames) + " of " +
                 std::to_string(range.end - range.begin) + " frames (frames " + std::to_string(range.begin) + ".." +
                 std::to_string(f - 1) + "); " + output + " is marked partial (attribute interrupted = " +
                 signal_name(signal) + ")");
    return interrupted_exit_code(signal);
}

}  // namespace

Command add_record_command(CLI::App& app) {
    auto options = std::make_shared<RecordOptions>();
    CLI::App* record = app.add_subcommand("record", "Record a session: every frame's pairs, stats and geometry to HDF5");
    record->footer(k_record_footer);
    record->add_option("inputs", options->inputs, "Mesh files, frame patterns, meshes with a point cache (body.obj@body.pc2) or scene.json manifests (as for check)")
        ->type_name("INPUT");
    record->add_option("--scene", options->scene, "A built-in scene instead of INPUT files: NAME[:PRESET] (" +
                                                      builtin_scene_list() + ")")
        ->type_name("NAME[:PRESET]");
    record->add_option("-o,--output", options->output, "The HDF5 file to write (replaced if it exists)")
        ->required()
        ->type_name("FILE");
    record->add_option("--frames", options->frames, "Frames to record: A:B (half-open), A:, :B or N")->type_name("A:B");
    record->add_option("--depth", options->depth, "GPU cull depth buffers: off or every:N (frames whose index is a multiple of N)")
        ->capture_default_str();
    record->add_option("--budget", options->budget, "Bound the file size (decimates depth buffers, then positions), e.g. 100M")
        ->type_name("SIZE");
    record->add_option("--queue-memory", options->queue, "Memory cap of frames waiting for the writer thread")
        ->type_name("SIZE")
        ->capture_default_str();
    record->add_option("--compression", options->compression,
                       "gzip level (with shuffle) of positions, pairs and triangles; 0 = uncompressed")
        ->check(whole_number(0, 9, "(a gzip level; 0: uncompressed)"))
        ->capture_default_str();
    add_engine_options(*record, options->engine);
    record->add_option("--writer-nice", options->writer_nice, "Nice increment of the writer thread (0 = same priority)")
        ->check(whole_number(0, 19, "(a nice increment)"))
        ->capture_default_str();
    record->add_option("--join", options->join,
                       "Under mpirun: virtual (FILE maps the ranks' parts, kept in FILE.parts/, which must stay with it) or "
                       "copy (one self-contained FILE; the parts are removed). Serial runs ignore it")
        ->check(CLI::IsMember({"virtual", "copy"}))
        ->capture_default_str();
    record->add_flag("--regions", options->regions,
                     "Record each frame's interpenetration regions and their curves (/regions; docs/explanation/regions.md)");
    CLI::Option* between = record->add_flag("--between-frames", options->between_frames,
                     "Also test each frame with the one before it, vertices moving linearly between them, and record "
                     "each interval's pairs, times of contact and pass-throughs (/intervals; "
                     "docs/explanation/between-frames.md)");
    record->add_option("--ccd-tolerance", options->ccd_tolerance,
                       "With --between-frames: the tolerance delta of the times of contact, in scene units (0: 1e-6 of "
                       "each interval's extent)")
        ->check(non_negative_number("in scene units (0: automatic)"))
        ->needs(between)
        ->type_name("D");
    record->add_flag("-q,--quiet", options->quiet, "Only the final line on stderr");
    return {record, [options] { return run_record(*options); }};
}

}  // namespace collidescope::app
