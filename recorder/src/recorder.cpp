// The recorder: copies each frame on the engine's thread, writes it on a writer thread.

#include "collidescope/recorder/recorder.hpp"

#include "file_budget.hpp"
#include "frame_queue.hpp"
#include "trace_file.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace collidescope::recorder {
namespace {

LargeVector<float> to_float(const std::vector<Vec3>& vertices) {
    LargeVector<float> out(vertices.size() * 3);
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (int axis = 0; axis < 3; ++axis) out[3 * v + static_cast<std::size_t>(axis)] = static_cast<float>(vertices[v][axis]);
    }
    return out;
}

// "run.h5: frame 37: cannot reserve ... (No space left on device); the 37 frames before it
// are intact and the file is left unfinished (partial)".
std::string write_error_line(const std::string& what, std::uint64_t intact, bool damaged) {
    if (damaged) {
        return what + "; the write failed inside the frame, so the file may not open (the " + std::to_string(intact) +
               " frames before it were flushed)";
    }
    return what + "; the " + std::to_string(intact) + " frames before it are intact and the file is left unfinished (partial)";
}

}  // namespace

struct Recorder::State {
    RecorderConfig config;
    std::vector<std::string> methods = method_names();
    std::vector<std::uint64_t> revisions;  ///< last topology revision recorded, per object
    bool first = true;
    TraceFile file;
    FrameQueue queue;
    FileBudget budget;
    RecordSummary summary;
    std::mutex error_mutex;
    std::exception_ptr error;
    std::thread writer;
    bool finished = false;

    State(RecorderConfig config_in, const SessionInfo& session, const Frame& first_frame)
        : config(std::move(config_in)),
          file(config.path, session, first_frame, methods, config.deflate_level),
          queue(config.queue_bytes),
          budget(config.budget_bytes, session.frame_end - session.frame_begin) {}

    void write_loop();
    void rethrow_writer_error();
    FrameRecord copy(const FrameReport& report);
};

void Recorder::State::write_loop() {
    h5::silence();
    // Below the engine's threads: on a machine with few cores, a writer competing for a core
    // stalls the engine's parallel loops. It catches up between frames (the queue absorbs it).
    if (config.writer_nice > 0) {
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), config.writer_nice);
    }
    FileBudget::Usage usage;
    try {
        while (std::optional<FrameRecord> record = queue.pop()) {
            TraceFile::Keep keep;
            keep.positions = budget.keep_positions(summary.frames);
            const bool has_depth = !record->depth_images.empty();
            keep.depth = has_depth && budget.keep_depth();
            file.append(*record, keep);
            summary.positions_dropped += keep.positions ? 0 : 1;
            summary.depth_frames += has_depth ? 1 : 0;
            summary.depth_dropped += has_depth && !keep.depth ? 1 : 0;
            ++summary.frames;
            if (config.budget_bytes > 0) {
                usage.rows = summary.frames;
                usage.positions_kept += keep.positions ? 1 : 0;
                usage.depth_kept += keep.depth ? 1 : 0;
                usage.depth_seen += has_depth ? 1 : 0;
                usage.file_bytes = file.file_bytes();
                usage.positions_bytes = file.positions_bytes();
                usage.depth_bytes = file.depth_bytes();
                budget.update(usage);
            }
        }
    } catch (const std::exception& failure) {
        std::lock_guard lock(error_mutex);
        error = std::make_exception_ptr(InputError(write_error_line(failure.what(), summary.frames, file.damaged())));
        queue.close(true);  // the engine's next push returns false and sees the error
    }
}

void Recorder::State::rethrow_writer_error() {
    std::lock_guard lock(error_mutex);
    if (error) std::rethrow_exception(error);
}

namespace {

// The methods' own details (schema 1.1 and 1.2): zeros and present = 0 when a method has none.
void copy_details(const FrameStats& stats, FrameRecord& record) {
    record.has_gpu = stats.gpu.has_value();
    for_each_gpu_value(stats.gpu.value_or(GpuFrameInfo{}), [&](const char*, double v, const char*) { record.gpu.push_back(v); });
    if (stats.gpu) {
        for (const GpuPassInfo& pass : stats.gpu->passes) {
            for_each_pass_field(pass, [&](const char*, std::uint64_t v) { record.gpu_passes.push_back(v); });
        }
        record.survivors.assign(stats.gpu->survivors.begin(), stats.gpu->survivors.end());
        record.depth_images = stats.gpu->depth_images;
    }
    record.has_aabb = stats.aabb.has_value();
    for_each_aabb_value(stats.aabb.value_or(AabbFrameInfo{}), [&](const char*, double v, const char*) { record.aabb.push_back(v); });
    record.has_decision = stats.decision.has_value();
    for_each_decision_value(stats.decision.value_or(DecisionInfo{}),
                            [&](const char*, double v, const char*) { record.decision.push_back(v); });
    record.has_hybrid = stats.hybrid.has_value();
    for_each_hybrid_value(stats.hybrid.value_or(HybridFrameInfo{}),
                          [&](const char*, double v, const char*) { record.hybrid.push_back(v); });
}

}  // namespace

FrameRecord Recorder::State::copy(const FrameReport& report) {
    FrameRecord record;
    record.frame = report.frame.index;
    const auto code = std::find(methods.begin(), methods.end(), report.stats.method);
    if (code == methods.end()) throw InputError(config.path.string() + ": unknown method " + report.stats.method);
    record.method = static_cast<std::uint8_t>(code - methods.begin());
    for_each_stage(report.stats.ms, [&](const char*, double value) { record.ms.push_back(value); });
    for_each_count(report.stats.counts, [&](const char*, std::uint64_t value) { record.counts.push_back(value); });
    record.pairs.assign(report.colliding_pairs.begin(), report.colliding_pairs.end());
    copy_details(report.stats, record);
    if (first) revisions.assign(report.frame.objects.size(), 0);
    for (std::size_t k = 0; k < report.frame.objects.size(); ++k) {
        const ObjectFrame& object = report.frame.objects[k];
        ObjectRecord out;
        if (first || object.topology->revision != revisions[k]) {
            out.new_topology = object.topology;
            revisions[k] = object.topology->revision;
        }
        out.positions = to_float(object.vertices);
        record.objects.push_back(std::move(out));
    }
    first = false;
    return record;
}

Recorder::Recorder(RecorderConfig config, SessionInfo session, const Frame& first_frame)
    : m_state(std::make_unique<State>(std::move(config), session, first_frame)) {
    if (m_state->methods.size() > 255) throw InputError("too many methods for the recording's enum");
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
    if (!m_state->queue.push(m_state->copy(report))) m_state->rethrow_writer_error();
}

RecordSummary Recorder::finish(const std::string& interrupted) {
    State& state = *m_state;
    state.finished = true;
    state.queue.close();
    if (state.writer.joinable()) state.writer.join();
    state.rethrow_writer_error();
    state.file.close();
    TraceFile::mark_finished(state.config.path, state.summary.frames, state.budget.positions_stride(), interrupted);
    state.summary.positions_stride = state.budget.positions_stride();
    state.summary.depth_stride = state.budget.depth_stride();
    state.summary.queue_peak_bytes = state.queue.peak_bytes();
    std::error_code error;
    state.summary.file_bytes = std::filesystem::file_size(state.config.path, error);
    return state.summary;
}

}  // namespace collidescope::recorder
