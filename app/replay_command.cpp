// `collidescope replay`: a recording -> annotated PNG frames, a contact sheet and/or a video clip, or two
// recordings side by side with --diff (replays/, docs/how-to/replay.md).

#include "commands.hpp"
#include "number_checks.hpp"
#include "frame_range.hpp"
#include "interrupt.hpp"
#include "named_cli_option.hpp"
#include "progress.hpp"
#include "ranks/ranks.hpp"

#include "collidescope/error.hpp"
#include "collidescope/replays/replay.hpp"

#include <malloc.h>

#include <charconv>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

namespace collidescope::app {
namespace {

struct ReplayCliOptions {
    std::vector<std::string> recordings;  ///< one, or two with --diff
    std::string output;                   ///< -o DIR ("" = no PNGs; then --video is needed)
    std::string video;                    ///< --video FILE.mp4|FILE.gif
    std::string frames;                   ///< "" = every recorded frame
    std::string size = "1280x720";
    std::string camera = "auto";
    std::string up;                       ///< "" = the recording's up axis, else z
    std::string show = "all";
    int threads = 0;
    GlBackend gl = GlBackend::Auto;
    std::string contact_sheet;
    replays::SheetSelection sheet_frames = replays::SheetSelection::Every;
    int sheet_count = 12;
    bool contact_moments = false;
    bool diff = false;
    bool quiet = false;
};

constexpr const char* k_replay_footer = R"(Writes DIR/frame_NNNN.png per recorded frame (NNNN = scene frame number), rendered offscreen
(OSMesa or EGL, see --gl) in several threads: the meshes (one colour per object), colliding
triangles red, triangles left in the GPU cull's PCS amber and culled ones dimmed, the recorded
depth buffers as thumbnails with a colour bar, a panel (frame, method and mode, the decision
and its inputs, time per stage, pairs, PCS per pass, queries, triangles per query, the view
matrix as a heat map) and a timeline of per-frame time coloured by mode. Layers for --show:
meshes, collisions, pcs, depth, overlay, timeline, legend (or all, none). Whatever the
recording lacks is said on the image and on stderr. Same recording and options: same bytes.
--diff A.h5 B.h5 writes DIR/diff_NNNN.png: the frames both hold, A left and B right, the pairs
only one of them found in green. --video FILE.mp4|FILE.gif encodes the frames as one clip
(H.264 MP4 or animated GIF, through FFmpeg's libraries), with or without -o DIR; a failed
clip leaves no file. --contact-moments (a recording made with record --between-frames) also
writes DIR/contact_NNNN.png for each interval from frame NNNN in which something passed through
(apart at both frames): the meshes at the first pass-through's time of contact, its pair red and
ringed; the timeline marks every such interval. See docs/how-to/replay.md.
SIGINT or SIGTERM stops after the frames being rendered: every PNG written is complete.
Under mpirun (docs/how-to/mpi.md) each rank renders one block of the frames into DIR, the same files
a serial replay writes; with --video (which then needs -o DIR) rank 0 encodes the clip from
them at the end; --diff runs serially only.
Exit codes: 0 written (--diff: same pairs), 1 (--diff only) the pairs differ, 2 error, 130 or
143 stopped by SIGINT or SIGTERM (with --video: the clip is not written).)";

void parse_image_size(const std::string& text, replays::ReplayOptions& options) {
    const std::size_t x = text.find('x');
    int width = 0;
    int height = 0;
    const bool ok = x != std::string::npos &&
                    std::from_chars(text.data(), text.data() + x, width).ptr == text.data() + x &&
                    std::from_chars(text.data() + x + 1, text.data() + text.size(), height).ptr ==
                        text.data() + text.size();
    if (!ok || width < 64 || height < 64 || width > 8192 || height > 8192) {
        throw InputError("--size must be WIDTHxHEIGHT, each 64 to 8192 pixels, not '" + text + "'");
    }
    options.width = width;
    options.height = height;
}

replays::ReplayOptions replay_options(const ReplayCliOptions& cli) {
    replays::ReplayOptions options;
    options.output_dir = cli.output;
    options.video = cli.video;
    if (!cli.video.empty()) replays::check_video_path(cli.video);
    if (!cli.frames.empty()) {
        // Scene frame numbers; the recording says which of them it holds.
        const FrameRange range = parse_frame_range(cli.frames, std::numeric_limits<std::uint32_t>::max());
        options.frame_begin = range.begin;
        options.frame_end = range.end;
    }
    parse_image_size(cli.size, options);
    options.camera = replays::parse_camera(cli.camera);
    if (!cli.up.empty()) options.camera.up = replays::parse_up_axis(cli.up);
    options.layers = replays::parse_layers(cli.show);
    options.threads = cli.threads;
    options.gl = cli.gl;
    options.contact_sheet = cli.contact_sheet;
    options.sheet_selection = cli.sheet_frames;
    options.sheet_count = cli.sheet_count;
    options.contact_moments = cli.contact_moments;
    return options;
}

// Under mpirun: this rank's block of the replayed frames (scene frame numbers), rendered with
// the camera, timeline and contact sheet choice of the whole replay; the sheet is rank 0's, and
// so is the clip, encoded from every rank's PNGs at the end (replay_in_parallel_end). Returns
// the scene frame numbers of the replayed frames.
std::vector<std::uint32_t> take_block(const std::string& recording, replays::ReplayOptions& options) {
    const std::vector<std::uint32_t> frames = replays::replayed_frames(recording, options);
    const FrameRange block = ranks::block({frames.front(), frames.back() + 1});
    options.part_begin = block.begin;
    options.part_end = block.end;
    options.video.clear();
    if (!ranks::leader()) options.contact_sheet.clear();
    return frames;
}

std::string png_name(std::uint32_t frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.png", frame);
    return name;
}

// Under mpirun, once every rank is done, rank 0 prints the serial run's `wrote` line and
// encodes the clip (--video) from the PNGs every rank wrote, in frame order.
void replay_in_parallel_end(const ReplayCliOptions& cli, const replays::ReplayOptions& options,
                            const std::vector<std::uint32_t>& frames, std::uint64_t written) {
    const std::string output = cli.output;
    const std::string first = png_name(frames.front()), last = png_name(frames.back());
    ranks::summary_line({double(written)}, [output, first, last](const std::vector<double>& sums) {
        return "wrote " + std::to_string(static_cast<std::uint64_t>(sums[0])) + " frames to " + output + " (" + first +
               " .. " + last + ")";
    }, true);
    if (cli.video.empty()) return;
    replays::ReplayOptions whole = options;
    whole.video = cli.video;
    const std::string recording = cli.recordings[0];
    ranks::when_done([recording, whole, frames] {
        std::vector<std::filesystem::path> pngs;
        for (const std::uint32_t frame : frames) pngs.push_back(whole.output_dir / png_name(frame));
        const replays::ReplaySummary clip = replays::encode_pngs_as_video(recording, pngs, whole);
        std::printf("video: %s (%llu frames at %g fps, %.2f s of encoding)\n", clip.video.c_str(),
                    static_cast<unsigned long long>(clip.frames), clip.video_fps, clip.video_seconds);
        std::fflush(stdout);
        return 0;
    });
}

std::string rate_line(const replays::ReplaySummary& summary, const replays::ReplayOptions& options) {
    char line[256];
    std::snprintf(line, sizeof line, "rendered %llu frames of %llu triangles at %dx%d in %.2f s (%.1f frames/s, %d threads, %s)",
                  static_cast<unsigned long long>(summary.frames), static_cast<unsigned long long>(summary.triangles),
                  options.width, options.height, summary.seconds,
                  summary.seconds > 0 ? double(summary.frames) / summary.seconds : 0.0, summary.threads,
                  summary.renderer.c_str());
    std::string text = line;
    if (summary.draw_seconds <= 0) return text;  // --diff does not time its steps
    std::snprintf(line, sizeof line, "; thread seconds: read %.2f, draw %.2f, read back %.2f, png %.2f",
                  summary.read_seconds, summary.draw_seconds, summary.readback_seconds, summary.png_seconds);
    text += line;
    if (summary.video.empty()) return text;
    std::snprintf(line, sizeof line, ", video %.2f", summary.video_seconds);
    return text + line;
}

// The argument combinations replay refuses, each with its one line.
void check_replay_arguments(const ReplayCliOptions& cli) {
    if (cli.diff && cli.contact_moments) {
        throw InputError("--contact-moments renders one recording's intervals: not with --diff");
    }
    if (cli.diff != (cli.recordings.size() == 2)) {
        throw InputError(cli.diff ? "--diff needs two recordings: replay --diff A.h5 B.h5 -o DIR"
                                  : "replay takes one recording (two with --diff)");
    }
    if (cli.output.empty() && (cli.diff || cli.video.empty())) {
        throw InputError(cli.diff ? "replay --diff needs -o DIR" : "replay needs -o DIR (PNG frames), --video FILE, or both");
    }
    if (cli.diff && !cli.video.empty()) throw InputError("--video does not go with --diff (use -o DIR)");
    if (ranks::parallel() && cli.diff) throw InputError("--diff does not run frame-parallel: run it without mpirun");
    if (ranks::parallel() && cli.output.empty()) {
        throw InputError("under mpirun, --video needs -o DIR: the ranks write the frames there, rank 0 encodes them");
    }
}

// The progress bar and the stop between frames. SIGINT or SIGTERM (mpirun's Ctrl-C) stops the
// replay between frames: the PNGs written so far stay, each complete; with --video, unwinding
// removes the unfinished clip.
class ReplayProgress {
public:
    struct Interrupted {};

    explicit ReplayProgress(const ReplayCliOptions& cli) : m_cli(cli) {}

    /// The replayer's FrameDone: advances the bar; throws Interrupted after a signal.
    void frame_done(std::uint64_t total) {
        // Under mpirun only rank 0 shows a bar (of its own block), so the ranks' bars do not garble.
        if (!m_bar && ranks::leader()) m_bar = std::make_unique<Progress>(total);
        if (m_bar) m_bar->advance();
        ++m_done;
        m_expected = total;
        if (m_interrupt.signal() != 0 && m_done < total) throw Interrupted{};
    }
    void finish() {
        if (m_bar) m_bar->finish();
    }
    /// After Interrupted: the line, and the exit code of the signal.
    int stopped() {
        finish();
        const int signal = m_interrupt.signal();
        // "replay: interrupted by SIGINT[; clip.mp4 not written]; 12 of 60 frames rendered[, every PNG in DIR complete]"
        std::string line = "replay: interrupted by " + signal_name(signal);
        if (!m_cli.video.empty()) line += "; " + m_cli.video + " not written";
        line += "; " + std::to_string(m_done) + " of " + std::to_string(m_expected) +
                (m_cli.contact_moments ? " images (frames and moments of contact) rendered" : " frames rendered");
        if (!m_cli.output.empty()) line += ", every PNG in " + m_cli.output + " complete";
        std::fprintf(stderr, "%s\n", line.c_str());
        return interrupted_exit_code(signal);
    }

private:
    const ReplayCliOptions& m_cli;
    const InterruptGuard m_interrupt;
    std::unique_ptr<Progress> m_bar;  // made at the first frame, when the number of frames is known
    std::uint64_t m_done = 0;
    std::uint64_t m_expected = 0;
};

// replay --diff: the side-by-side frames and the pairs each recording alone has.
int run_replay_diff(const ReplayCliOptions& cli, const replays::ReplayOptions& options, ReplayProgress& progress) {
    replays::ReplaySummary summary;
    try {
        summary = replays::replay_diff(cli.recordings[0], cli.recordings[1], options,
                                       [&](std::uint64_t total) { progress.frame_done(total); });
    } catch (const ReplayProgress::Interrupted&) {
        return progress.stopped();
    }
    progress.finish();
    std::printf("wrote %llu side-by-side frames to %s (diff_NNNN.png): %llu pairs only in %s, %llu only in %s\n",
                static_cast<unsigned long long>(summary.frames), cli.output.c_str(),
                static_cast<unsigned long long>(summary.only_in_a), cli.recordings[0].c_str(),
                static_cast<unsigned long long>(summary.only_in_b), cli.recordings[1].c_str());
    if (!cli.quiet) std::fprintf(stderr, "%s\n", rate_line(summary, options).c_str());
    return summary.only_in_a + summary.only_in_b == 0 ? 0 : 1;
}

// What a replay wrote: the notes, the rate, the frames, the clip and the contact sheet.
void print_replay_summary(const ReplayCliOptions& cli, const replays::ReplayOptions& options,
                          const std::vector<std::uint32_t>& replayed, const replays::ReplaySummary& summary) {
    if (ranks::leader()) {
        for (const std::string& note : summary.notes) std::fprintf(stderr, "replay: note: %s\n", note.c_str());
    }
    if (!cli.quiet) std::fprintf(stderr, "%s\n", rate_line(summary, options).c_str());
    if (ranks::parallel()) {
        replay_in_parallel_end(cli, options, replayed, summary.frames);
    } else if (!summary.files.empty()) {
        std::printf("wrote %llu frames to %s (%s .. %s)\n", static_cast<unsigned long long>(summary.frames),
                    cli.output.c_str(), summary.files.front().filename().c_str(), summary.files.back().filename().c_str());
    }
    if (!summary.video.empty()) {
        std::printf("video: %s (%llu frames at %g fps, %.2f s of encoding)\n", summary.video.c_str(),
                    static_cast<unsigned long long>(summary.frames), summary.video_fps, summary.video_seconds);
    }
    if (!summary.contact_sheet.empty()) std::printf("contact sheet: %s\n", summary.contact_sheet.c_str());
    if (options.contact_moments && ranks::parallel()) {
        ranks::summary_line({double(summary.moment_files.size())}, [](const std::vector<double>& sums) {
            return "moments of contact: " + std::to_string(static_cast<std::uint64_t>(sums[0])) + " (contact_NNNN.png)";
        }, true);
    } else if (options.contact_moments) {
        if (summary.moment_files.empty()) {
            std::printf("moments of contact: none (no pass-through between the replayed frames)\n");
        } else {
            std::printf("moments of contact: %zu (%s .. %s)\n", summary.moment_files.size(),
                        summary.moment_files.front().filename().c_str(), summary.moment_files.back().filename().c_str());
        }
    }
}

int run_replay(const ReplayCliOptions& cli) {
    check_replay_arguments(cli);
    replays::ReplayOptions options = replay_options(cli);
    std::vector<std::uint32_t> replayed;
    if (ranks::parallel()) replayed = take_block(cli.recordings[0], options);
    // Every frame allocates a few image-sized buffers (3.7 MB at 1280x720: read back, PNG
    // filter rows, deflate output). Above glibc's mmap threshold each is mapped and unmapped
    // again, with page faults on every frame (measured: 8-10% of a frame at 1280x720); keep
    // them in the heap, where freed blocks are reused.
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    ReplayProgress progress(cli);
    if (cli.diff) return run_replay_diff(cli, options, progress);
    replays::ReplaySummary summary;
    try {
        summary = replays::replay(cli.recordings[0], options, [&](std::uint64_t total) { progress.frame_done(total); });
    } catch (const ReplayProgress::Interrupted&) {
        return progress.stopped();
    }
    progress.finish();
    print_replay_summary(cli, options, replayed, summary);
    return 0;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
    auto options = std::make_shared<ReplayCliOptions>();
    CLI::App* replay = app.add_subcommand("replay", "Render a recording as annotated PNG frames and/or a video clip, offscreen (or --diff two)");
    replay->footer(k_replay_footer);
    replay->add_option("recordings", options->recordings, "The recording (two with --diff)")
        ->required()
        ->type_name("RECORDING.h5");
    replay->add_option("-o,--output", options->output,
                       "Directory for the PNGs (created when missing); optional with --video")
        ->type_name("DIR");
    replay->add_option("--video", options->video,
                       "Also encode the frames as a clip: FILE.mp4 (H.264) or FILE.gif, at the recording's fps (30 "
                       "when it has none)")
        ->type_name("FILE");
    replay->add_option("--frames", options->frames, "Scene frames to replay: A:B (half-open), A:, :B or N")
        ->type_name("A:B");
    replay->add_option("--size", options->size, "Image size in pixels")->type_name("WxH")->capture_default_str();
    replay->add_option("--camera", options->camera,
                       "auto, orbit[:DEG_PER_FRAME], focus (follows the collisions) or fixed:EX,EY,EZ[:TX,TY,TZ]")
        ->capture_default_str();
    replay->add_option("--up", options->up, "The axis that points up on screen: x, y or z (default: the recording's, else z)")
        ->type_name("x|y|z");
    replay->add_option("--show", options->show, "Layers: meshes,collisions,pcs,depth,overlay,timeline,legend,regions | all | none")
        ->type_name("LIST")
        ->capture_default_str();
    replay->add_option("--threads", options->threads, "Render threads, each with its own GL context; 0 = all hardware threads")
        ->check(whole_number(0, 1024, "of render threads (0: all hardware threads)"))
        ->capture_default_str();
    add_named_option(*replay, "--gl", options->gl, k_gl_backend_names,
                     "GL context: auto (a GPU through EGL if any, else OSMesa), osmesa or egl");
    replay->add_option("--contact-sheet", options->contact_sheet, "Also write a grid of selected frames to this PNG")
        ->type_name("FILE.png");
    add_named_option(*replay, "--sheet-frames", options->sheet_frames, replays::k_sheet_selection_names,
                     "Contact sheet frames: every, collisions or slowest");
    replay->add_option("--sheet-count", options->sheet_count, "Frames on the contact sheet, at most")
        ->check(whole_number(1, 10000, "of frames"))
        ->capture_default_str();
    replay->add_flag("--contact-moments", options->contact_moments,
                     "Also write DIR/contact_NNNN.png for each interval from frame NNNN with a pass-through (record "
                     "--between-frames): the meshes at the first pass-through's time of contact, its pair ringed");
    replay->add_flag("--diff", options->diff, "Compare two recordings side by side, differing pairs highlighted");
    replay->add_flag("-q,--quiet", options->quiet, "No rate line on stderr");
    return {replay, [options] { return run_replay(*options); }};
}

}  // namespace collidescope::app
