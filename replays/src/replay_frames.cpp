// replay(): a recording -> one annotated PNG per frame, rendered in parallel, and the contact
// sheet.

#include "collidescope/replays/replay.hpp"

#include "contact_sheet.hpp"
#include "frame_data.hpp"
#include "open_video.hpp"
#include "ordered_video.hpp"
#include "png.hpp"
#include "render_pool.hpp"
#include "replay_common.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>

namespace collidescope::replays {
namespace {

// Seconds since the last lap.
class StepClock {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - m_last).count();
        m_last = now;
        return seconds;
    }

private:
    std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

std::filesystem::path frame_file(const std::filesystem::path& dir, const char* prefix, std::uint32_t frame) {
    char name[48];
    std::snprintf(name, sizeof name, "%s_%04u.png", prefix, frame);
    return dir / name;
}


// The clip, opened before any frame is rendered (a bad path fails at once), at clip_fps.
std::unique_ptr<OrderedVideo> open_ordered_video(const RecordingData& data, const ReplayOptions& options,
                                                 ReplaySummary& summary) {
    if (options.video.empty()) return nullptr;
    VideoSettings settings;
    settings.path = options.video;
    settings.width = options.width;
    settings.height = options.height;
    settings.fps = clip_fps(data.recording());
    summary.video = options.video;
    summary.video_fps = settings.fps;
    return std::make_unique<OrderedVideo>(open_video(settings));
}

// --camera region:ID: region ID's box in the frames it lives, framed as --camera focus frames
// the collisions. An error when the recording has no regions or the id is not in the frames.
std::vector<Framing> region_path(std::uint32_t id, RecordingData& data, const std::vector<std::uint64_t>& rows,
                                 const Bounds& bounds) {
    if (!data.recording().has_regions()) {
        throw InputError(data.path() + ": --camera region:" + std::to_string(id) +
                         " needs a recording made with record --regions (it has no /regions)");
    }
    std::vector<Bounds> boxes(rows.size());
    std::uint32_t largest = 0;
    bool seen = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        for (const recorder::RecordedRegion& region : data.recording().regions(rows[i], false)) {
            largest = std::max(largest, region.id);
            if (region.id != id) continue;
            boxes[i].add(region.box[0], region.box[1], region.box[2]);
            boxes[i].add(region.box[3], region.box[4], region.box[5]);
            seen = true;
        }
    }
    if (!seen) {
        throw InputError(data.path() + ": --camera region:" + std::to_string(id) + ": no such region in the replayed frames" +
                         (largest > 0 ? " (ids 1.." + std::to_string(largest) + ")" : " (they have no regions)"));
    }
    return focus_path(boxes, bounds);
}

// --camera focus: the region to frame in each replayed frame; empty for other cameras, and
// when no replayed frame has collisions (the camera then frames the whole scene, as auto).
std::vector<Framing> focus_of(const CameraSpec& camera, RecordingData& data, const std::vector<std::uint64_t>& rows,
                              const Bounds& bounds, ReplaySummary& summary) {
    if (camera.kind == CameraSpec::Kind::Region) return region_path(camera.region, data, rows, bounds);
    if (camera.kind != CameraSpec::Kind::Focus) return {};
    const std::vector<Bounds> colliding = data.collision_bounds(rows);
    if (std::all_of(colliding.begin(), colliding.end(), [](const Bounds& box) { return box.empty(); })) {
        summary.notes.push_back("no colliding triangles in the replayed frames: --camera focus frames the whole scene");
        return {};
    }
    return focus_path(colliding, bounds);
}

bool whole_replay(const ReplayOptions& options) { return options.part_begin == 0 && options.part_end == UINT32_MAX; }

// The ordinals (positions among the replayed `rows`) this process renders: those in the
// options' part, then the contact sheet's `picked` frames outside it (rendered for the sheet
// alone). `in_part[i]`: ordinal i is in the part (its PNG is written).
std::vector<std::uint64_t> render_jobs(const RecordingData& data, const std::vector<std::uint64_t>& rows,
                                       const ReplayOptions& options, const std::vector<std::uint64_t>& picked,
                                       std::vector<bool>& in_part) {
    in_part.assign(rows.size(), false);
    std::vector<std::uint64_t> jobs;
    for (std::uint64_t i = 0; i < rows.size(); ++i) {
        const std::uint32_t frame = data.indices()[rows[i]];
        in_part[i] = frame >= options.part_begin && frame < options.part_end;
        if (in_part[i]) jobs.push_back(i);
    }
    for (const std::uint64_t i : picked) {
        if (!in_part[i]) jobs.push_back(i);
    }
    return jobs;
}

}  // namespace

// The clip's frame rate (replay_common.hpp): the recording's `fps`; else, when it has frame times (a point cache
// with times but no rate), one over the median step between them; else 30.
double clip_fps(const recorder::Recording& recording) {
    if (recording.fps() > 0) return recording.fps();
    const std::vector<double> times = recording.frame_times();
    std::vector<double> steps;
    for (std::size_t k = 1; k < times.size(); ++k) {
        if (times[k] > times[k - 1]) steps.push_back(times[k] - times[k - 1]);
    }
    if (steps.empty()) return 30.0;
    std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
    return std::clamp(1.0 / steps[steps.size() / 2], 1.0, 1000.0);
}

std::vector<std::uint32_t> replayed_frames(const std::filesystem::path& recording, const ReplayOptions& options) {
    const RecordingData data(recording);
    std::vector<std::uint32_t> frames;
    for (const std::uint64_t row : replay_rows(data, options)) frames.push_back(data.indices()[row]);
    return frames;
}

CameraSpec resolved_camera(const CameraSpec& camera, const RecordingData& data) {
    CameraSpec resolved = camera;
    if (resolved.up == 0) resolved.up = data.recording().up_axis();
    return resolved;
}

void prepare_output_dir(const std::filesystem::path& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error || !std::filesystem::is_directory(dir)) {
        throw InputError(dir.string() + ": cannot create the output directory" +
                         (error ? " (" + error.message() + ")" : std::string()));
    }
}

std::vector<std::uint64_t> replay_rows(const RecordingData& data, const ReplayOptions& options) {
    std::vector<std::uint64_t> rows = data.rows_in(options.frame_begin, options.frame_end);
    if (rows.empty()) {
        throw InputError(data.path() + ": no recorded frame in frames " + std::to_string(options.frame_begin) + ":" +
                         (options.frame_end == UINT32_MAX ? std::string() : std::to_string(options.frame_end)) +
                         (data.rows() == 0 ? std::string(" (the recording has no complete frame)")
                                           : " (recorded: frames " + std::to_string(data.indices().front()) + " to " +
                                                 std::to_string(data.indices().back()) + ")"));
    }
    return rows;
}

SessionView session_view(const RecordingData& data) {
    SessionView session;
    session.file = data.path();
    const std::string preset = data.attribute("scene_preset");
    session.scene = data.attribute("scene") + (preset.empty() ? "" : " (" + preset + ")");
    session.method = data.attribute("method");
    session.depth = data.attribute("depth");
    session.frames = data.rows();
    session.object_names = data.object_names();
    session.totals = &data.totals();
    session.modes = &data.modes();
    session.indices = &data.indices();
    session.lives = &data.lives();
    session.pass_through_rows = &data.pass_through_rows();
    return session;
}

namespace {

// What every frame job of one replay shares: the frames, the camera, the layout, the contact
// sheet's picks, and which ordinals this process renders.
struct ReplayPlan {
    std::vector<std::uint64_t> rows;   ///< recording rows replayed, in order (ordinal i -> rows[i])
    Bounds bounds;
    CameraSpec camera;
    std::vector<Framing> focus;        ///< per ordinal, for --camera focus; else empty
    FrameLayout layout;
    SessionView session;
    std::vector<double> totals;        ///< per ordinal: the frame's total ms
    std::vector<std::uint64_t> pairs;  ///< per ordinal: its colliding pairs
    std::set<std::uint64_t> on_sheet;  ///< ordinals the contact sheet shows
    TileSize tile;                     ///< a sheet tile's size
    std::vector<bool> in_part;         ///< ordinal i is in this process's part (its PNG is written)
    std::vector<std::uint64_t> jobs;   ///< ordinals to render: the part's, then the sheet's others
    std::uint64_t own_frames = 0;      ///< ordinals in the part
    /// --contact-moments: ordinals in the part whose interval into the next row has a
    /// pass-through; rendered after `jobs`.
    std::vector<std::uint64_t> moments;
};

// --contact-moments: the ordinals in the part whose row is followed by a pass-through interval.
std::vector<std::uint64_t> moment_jobs(const RecordingData& data, const ReplayPlan& plan, const ReplayOptions& options) {
    if (!options.contact_moments) return {};
    if (!data.recording().has_intervals()) {
        throw InputError(data.path() + ": --contact-moments needs a recording made with record --between-frames (it has "
                         "no /intervals)");
    }
    if (options.output_dir.empty()) throw InputError("--contact-moments writes PNGs: give -o DIR");
    const std::vector<std::uint64_t>& rows = data.pass_through_rows();
    std::vector<std::uint64_t> out;
    for (std::uint64_t i = 0; i < plan.rows.size(); ++i) {
        if (plan.in_part[i] && std::binary_search(rows.begin(), rows.end(), plan.rows[i] + 1)) out.push_back(i);
    }
    return out;
}

ReplayPlan plan_replay(RecordingData& data, const ReplayOptions& options, ReplaySummary& summary) {
    ReplayPlan plan;
    plan.rows = replay_rows(data, options);
    plan.bounds = data.bounds(plan.rows);
    plan.camera = resolved_camera(options.camera, data);
    plan.focus = focus_of(plan.camera, data, plan.rows, plan.bounds, summary);
    plan.layout = frame_layout(options.width, options.height, options.layers);
    plan.session = session_view(data);
    for (const std::uint64_t row : plan.rows) {
        plan.totals.push_back(data.totals()[row]);
        plan.pairs.push_back(data.pair_counts()[row]);
    }
    const std::vector<std::uint64_t> picked =
        options.contact_sheet.empty()
            ? std::vector<std::uint64_t>{}
            : select_sheet_frames(options.sheet_selection, options.sheet_count, plan.totals, plan.pairs);
    plan.on_sheet = std::set<std::uint64_t>(picked.begin(), picked.end());
    // The sheet shows each frame's meshes (the scene's part of the image); its captions and
    // header carry the rest.
    plan.tile = sheet_tile_size(plan.layout.scene.w, plan.layout.scene.h);
    plan.jobs = render_jobs(data, plan.rows, options, picked, plan.in_part);
    plan.own_frames = static_cast<std::uint64_t>(std::count(plan.in_part.begin(), plan.in_part.end(), true));
    plan.moments = moment_jobs(data, plan, options);
    return plan;
}

// One rendered frame, before it goes to the PNG, the sheet and the clip.
struct RenderedFrame {
    FrameData frame;
    std::vector<std::uint8_t> rgba;
    double read = 0;  ///< seconds per step
    double draw = 0;
    double readback = 0;
};

// What the replayed frames held, for the notes at the end (layers asked for but not recorded).
struct Seen {
    bool depth = false;
    bool pcs = false;
    bool decision = false;
    std::uint64_t dropped = 0;  ///< frames whose positions the recording dropped
};

// Ordinal i's frame: read (under the reader's lock: one reader at a time), drawn and read back.
// With `moment`, the moment of first contact between ordinal i's row and the next.
RenderedFrame render_frame(RenderThread& thread, RecordingData& data, std::mutex& reader_lock,
                           const ReplayPlan& plan, const ReplayOptions& options, std::uint64_t i, bool moment = false) {
    StepClock clock;
    RenderedFrame out;
    {
        const std::lock_guard<std::mutex> guard(reader_lock);
        out.frame = moment ? data.load_moment(plan.rows[i] + 1, i) : data.load(plan.rows[i], i);
    }
    out.read = clock.lap();
    const Camera camera = make_camera(plan.camera, plan.bounds, plan.layout.scene, i, plan.rows.size(),
                                      plan.focus.empty() ? nullptr : &plan.focus[i]);
    thread.renderer->clear();
    thread.renderer->draw(out.frame, camera, options.layers);
    thread.overlay->draw_frame(out.frame, plan.session, plan.layout, options.layers, &camera);
    out.draw = clock.lap();
    out.rgba = thread.renderer->read_rgba();
    out.readback = clock.lap();
    return out;
}

// Ordinal i's sheet tile: the scene's part of the image, scaled down, with its caption.
SheetTile sheet_tile(const RenderedFrame& rendered, const ReplayPlan& plan, const ReplayOptions& options,
                     std::uint64_t i) {
    const Rect& scene = plan.layout.scene;
    const FrameData& frame = rendered.frame;
    return {downscale(crop(rendered.rgba, options.width, scene.x, scene.y, scene.w, scene.h), scene.w, scene.h,
                      plan.tile.width, plan.tile.height),
            frame.frame, frame_mode(frame.method, frame.decision), frame.method, frame.colliding.size(),
            plan.totals[i]};
}

// The notes a replay ends with: layers asked for that the recording lacks, frames without meshes.
void add_notes(const ReplayOptions& options, const ReplayPlan& plan, const Seen& seen, ReplaySummary& summary) {
    if ((options.layers & k_layer_depth) != 0 && !seen.depth) {
        summary.notes.push_back("no depth buffers in this recording (record --method gpu --depth every:N): no thumbnails");
    }
    if ((options.layers & k_layer_pcs) != 0 && !seen.pcs) {
        summary.notes.push_back("no GPU cull state in this recording (method " + plan.session.method +
                                "): PCS and culled triangles not shown");
    }
    if ((options.layers & k_layer_overlay) != 0 && !seen.decision) {
        summary.notes.push_back("no decisions in this recording (record --method adaptive): the panel says not recorded");
    }
    if (seen.dropped > 0) {
        summary.notes.push_back("the vertex positions of " + std::to_string(seen.dropped) + " of " +
                                std::to_string(plan.own_frames) +
                                " frames were not recorded (record --budget): those frames show no meshes");
    }
}

}  // namespace

ReplaySummary replay(const std::filesystem::path& recording, const ReplayOptions& options, const FrameDone& frame_done) {
    if (!options.video.empty() && !whole_replay(options)) {
        throw InputError(options.video.string() + ": a clip needs every replayed frame in one process, not a part");
    }
    RecordingData data(recording);
    ReplaySummary summary;
    const ReplayPlan plan = plan_replay(data, options, summary);
    const bool pngs = !options.output_dir.empty();
    if (pngs) prepare_output_dir(options.output_dir);
    const std::unique_ptr<OrderedVideo> video = open_ordered_video(data, options, summary);

    std::vector<std::filesystem::path> files(plan.rows.size());
    std::vector<std::filesystem::path> moment_files(plan.moments.size());
    std::map<std::uint64_t, SheetTile> tiles;
    Seen seen;
    std::mutex reader_lock;
    std::mutex done_lock;
    const auto start = std::chrono::steady_clock::now();
    summary.renderer = run_parallel(options.gl, options.threads, plan.jobs.size() + plan.moments.size(), options.width,
                                    options.height, [&](RenderThread& thread, std::uint64_t job) {
        if (job >= plan.jobs.size()) {  // a moment of contact: its own PNG, nothing else
            const std::uint64_t m = job - plan.jobs.size();
            const RenderedFrame rendered = render_frame(thread, data, reader_lock, plan, options, plan.moments[m], true);
            moment_files[m] = frame_file(options.output_dir, "contact", rendered.frame.frame);
            write_png(moment_files[m], rendered.rgba, options.width, options.height);
            const std::lock_guard<std::mutex> guard(done_lock);
            if (frame_done) frame_done(plan.own_frames + plan.moments.size());  // may stop the replay (a signal)
            return;
        }
        const std::uint64_t i = plan.jobs[job];
        RenderedFrame rendered = render_frame(thread, data, reader_lock, plan, options, i);
        StepClock clock;
        std::filesystem::path file;
        if (pngs && plan.in_part[i]) {
            file = frame_file(options.output_dir, "frame", rendered.frame.frame);
            write_png(file, rendered.rgba, options.width, options.height);
        }
        const double png = clock.lap();
        const bool on_sheet = plan.on_sheet.count(i) != 0;
        SheetTile tile = on_sheet ? sheet_tile(rendered, plan, options, i) : SheetTile{};
        if (video) video->add(i, std::move(rendered.rgba));
        const std::lock_guard<std::mutex> guard(done_lock);
        if (on_sheet) tiles[i] = std::move(tile);
        if (!plan.in_part[i]) return;  // rendered for the contact sheet alone
        const FrameData& frame = rendered.frame;
        files[i] = file;
        summary.read_seconds += rendered.read;
        summary.draw_seconds += rendered.draw;
        summary.readback_seconds += rendered.readback;
        summary.png_seconds += png;
        if (job == 0) {
            for (const ObjectFrame& object : frame.objects) summary.triangles += object.triangles->size();
        }
        seen.depth = seen.depth || !frame.depth_images.empty();
        seen.pcs = seen.pcs || frame.pcs_recorded;
        seen.decision = seen.decision || !frame.decision.empty();
        seen.dropped += frame.positions_dropped ? 1 : 0;
        ++summary.frames;
        if (frame_done) frame_done(plan.own_frames + plan.moments.size());
    });
    for (const std::filesystem::path& file : files) {
        if (!file.empty()) summary.files.push_back(file);
    }
    summary.moment_files = std::move(moment_files);
    if (video) {
        video->finish(plan.rows.size());
        summary.video_seconds = video->seconds();
    }
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary.threads = render_threads(options.threads, plan.jobs.size() + plan.moments.size());
    add_notes(options, plan, seen, summary);
    if (!options.contact_sheet.empty()) {
        std::vector<SheetTile> ordered;
        for (auto& [i, one] : tiles) ordered.push_back(std::move(one));
        write_contact_sheet(options.contact_sheet, ordered, plan.tile, plan.session, options.sheet_selection, options.gl);
        summary.contact_sheet = options.contact_sheet;
    }
    return summary;
}

}  // namespace collidescope::replays
