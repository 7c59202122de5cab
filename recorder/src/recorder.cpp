// The recorder: copies each frame on the engine's thread, writes it on a writer thread.

#include "collidescope/recorder/recorder.hpp"

#include "file_budget.hpp"
#include "frame_copier.hpp"
#include "frame_queue.hpp"
#include "recording_writer.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/regions.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace collidescope::recorder {
namespace {

/// Most frames one flush writes (group commit): bounds what a killed recording can lose of the
/// frames the writer had already taken from the queue.
constexpr std::size_t k_max_frames_per_flush = 16;

// "run.h5: frame 37: cannot reserve ... (No space left on device); the 37 frames before it
// are intact and the file is left unfinished (partial)".
std::string write_error_line(const std::string& what, std::uint64_t intact, bool damaged) {
    if (damaged) {
        return what + "; the write failed inside the frame, so the file may not open (the " + std::to_string(intact) +
               " frames before it were flushed)";
    }
    return what + "; the " + std::to_string(intact) + " frames before it are intact and the file is left unfinished (partial)";
}

// A frame's regions, flattened as /regions stores them.
RegionsRecord flatten(const std::vector<Region>& regions) {
    RegionsRecord out;
    for (const Region& region : regions) {
        out.table.insert(out.table.end(),
                         {region.id, region.obj_a, region.obj_b, region.pairs,
                          static_cast<std::uint32_t>(region.triangles_a.size()),
                          static_cast<std::uint32_t>(region.triangles_b.size()), region.loops});
        out.measures.insert(out.measures.end(), {region.curve_length, region.coplanar_area, region.box.min().x(),
                                                 region.box.min().y(), region.box.min().z(), region.box.max().x(),
                                                 region.box.max().y(), region.box.max().z()});
        out.penetration.insert(out.penetration.end(), {region.inside_area_a, region.inside_area_b, region.depth});
        out.curves.push_back(region.curves.size());
        for (const IntersectionCurve& curve : region.curves) {
            out.closed.push_back(curve.closed ? 1 : 0);
            out.points.push_back(curve.points.size());
            for (const Vec3& p : curve.points) out.xyz.insert(out.xyz.end(), {p.x(), p.y(), p.z()});
        }
        out.predecessor_counts.push_back(region.predecessors.size());
        out.predecessors.insert(out.predecessors.end(), region.predecessors.begin(), region.predecessors.end());
    }
    return out;
}

// The interval's contacts and counts, as /intervals stores them.
IntervalRecord flatten(const IntervalResult& result) {
    IntervalRecord out;
    const IntervalStats& s = result.stats;
    const std::uint64_t counts[7] = {s.candidate_pairs, s.start_contacts, s.primitive_queries, s.inclusion_boxes,
                                     s.contacts,        s.pass_throughs,  s.unresolved};
    std::copy(std::begin(counts), std::end(counts), out.counts);
    out.ms[0] = s.broad_ms, out.ms[1] = s.narrow_ms, out.ms[2] = s.ms;
    out.tolerance = s.tolerance;
    for (const IntervalContact& c : result.contacts) {
        out.pairs.push_back(c.pair);
        out.toi.push_back(c.toi);
        out.flags.push_back(static_cast<std::uint8_t>((c.pass_through ? schema::k_flag_pass_through : 0) |
                                                      (c.resolved ? 0 : schema::k_flag_unresolved)));
    }
    return out;
}

// A frame whose vertices the recorder owns: the engine's frame may view memory that is only
// valid during its Pipeline::process, and the next interval needs it after.
Frame owned_copy(const Frame& frame) {
    Frame out;
    out.index = frame.index;
    for (const ObjectFrame& object : frame.objects) {
        out.objects.push_back({object.topology, std::vector<Vec3>(object.vertices.begin(), object.vertices.end())});
    }
    return out;
}

}  // namespace

struct Recorder::State {
    RecorderConfig config;
    FrameCopier copier;
    RecordingWriter file;
    FrameQueue queue;
    FileBudget budget;
    RecordSummary summary;
    std::mutex error_mutex;
    std::exception_ptr error;
    std::thread writer;
    bool finished = false;
    bool regions = false;        ///< SessionInfo::regions: find and follow them per frame
    RegionTracker tracker;
    std::vector<Region> last_regions;  ///< the last frame's (last_regions())
    SessionInfo info;                  ///< the session (names for the between-frames errors)
    std::optional<BetweenFrames> between;  ///< SessionInfo::between_frames
    std::optional<Frame> previous;         ///< the last frame, owned (between frames only)

    State(RecorderConfig config_in, const SessionInfo& session, const Frame& first_frame)
        : config(std::move(config_in)),
          copier(config.path.string()),
          file(config.path, session, first_frame, copier.methods(), config.deflate_level),
          queue(config.queue_bytes),
          budget(config.budget_bytes, session.frame_end - session.frame_begin),
          regions(session.regions),
          info(session) {
        if (session.between_frames) {
            BetweenFramesOptions options;
            options.tolerance = session.ccd_tolerance;
            options.self_collision = session.self_collision;
            between.emplace(options);
        }
    }

    void write_loop();
    void rethrow_writer_error();
};

void Recorder::State::write_loop() {
    h5::silence();
    // Below the engine's threads: on a machine with few cores, a writer competing for a core
    // stalls the engine's parallel loops. It catches up between frames (the queue absorbs it).
    if (config.writer_nice > 0) {
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), config.writer_nice);
    }
    FileBudget::Usage usage;
    // Every frame waiting is written at once (one append per dataset, one flush): a writer
    // that fell behind catches up at a fraction of the per-frame cost. With --budget, one frame
    // at a time, so that the budget sees the file after every frame as it plans the next.
    const std::size_t batch = config.budget_bytes > 0 ? 1 : k_max_frames_per_flush;
    try {
        for (FrameQueue::Taken taken; !(taken = queue.take_waiting(batch)).records.empty();) {
            const std::vector<FrameRecord>& records = taken.records;
            std::vector<RecordingWriter::Keep> keeps(records.size());
            for (std::size_t i = 0; i < records.size(); ++i) {
                keeps[i].positions = budget.keep_positions(summary.frames + i);
                keeps[i].depth = !records[i].depth_images.empty() && budget.keep_depth();
            }
            file.append(records, keeps);
            for (std::size_t i = 0; i < records.size(); ++i) {
                const bool has_depth = !records[i].depth_images.empty();
                summary.positions_dropped += keeps[i].positions ? 0 : 1;
                summary.depth_frames += has_depth ? 1 : 0;
                summary.depth_dropped += has_depth && !keeps[i].depth ? 1 : 0;
                ++summary.frames;
                usage.positions_kept += keeps[i].positions ? 1 : 0;
                usage.depth_kept += keeps[i].depth ? 1 : 0;
                usage.depth_seen += has_depth ? 1 : 0;
            }
            queue.release(taken.bytes);
            if (config.budget_bytes > 0) {
                usage.rows = summary.frames;
                usage.file_bytes = file.file_bytes();
                usage.positions_bytes = file.positions_bytes();
                usage.depth_bytes = file.depth_bytes();
                budget.update(usage);
            }
        }
    } catch (const std::exception& failure) {
        std::lock_guard lock(error_mutex);
        error = std::make_exception_ptr(InputError(write_error_line(failure.what(), file.frames_written(), file.damaged())));
        queue.close(true);  // the engine's next push returns false and sees the error
    }
}

void Recorder::State::rethrow_writer_error() {
    std::lock_guard lock(error_mutex);
    if (error) std::rethrow_exception(error);
}

Recorder::Recorder(RecorderConfig config, SessionInfo session, const Frame& first_frame)
    : m_state(std::make_unique<State>(std::move(config), session, first_frame)) {
    m_state->writer = std::thread([state = m_state.get()] { state->write_loop(); });
}

Recorder::~Recorder() {
    if (!m_state || m_state->finished) return;
    // Keep what is queued: those frames are finished. The file stays unmarked (not finished).
    m_state->queue.close();
    if (m_state->writer.joinable()) m_state->writer.join();
    try {
        m_state->file.close();
    } catch (...) {  // a destructor must not throw; the caller is already failing
    }
}

void Recorder::on_frame(const FrameReport& report) {
    m_state->rethrow_writer_error();
    FrameRecord record = m_state->copier.copy(report);
    if (m_state->regions) {
        m_state->last_regions = find_regions(report.frame, report.colliding_pairs);
        m_state->tracker.update(report.stats.frame, m_state->last_regions);
        record.regions = flatten(m_state->last_regions);
    }
    if (m_state->between) {
        if (m_state->previous) {
            try {
                record.interval = flatten(m_state->between->detect(*m_state->previous, report.frame));
            } catch (const InputError& error) {
                throw InputError("scene '" + m_state->info.scene + "': " + with_object_names(error.what(), m_state->info.object_names));
            }
        }
        m_state->previous = owned_copy(report.frame);
    }
    if (!m_state->queue.push(std::move(record))) m_state->rethrow_writer_error();
}

const std::vector<Region>& Recorder::last_regions() const { return m_state->last_regions; }

RecordSummary Recorder::finish(const std::string& interrupted) {
    State& state = *m_state;
    state.finished = true;
    state.queue.close();
    if (state.writer.joinable()) state.writer.join();
    state.rethrow_writer_error();
    state.file.close();
    RecordingWriter::mark_finished(state.config.path, state.summary.frames, state.budget.positions_stride(), interrupted);
    state.summary.positions_stride = state.budget.positions_stride();
    state.summary.depth_stride = state.budget.depth_stride();
    state.summary.queue_peak_bytes = state.queue.peak_bytes();
    std::error_code error;
    state.summary.file_bytes = std::filesystem::file_size(state.config.path, error);
    return state.summary;
}

}  // namespace collidescope::recorder
