// The recorder: copies each frame on the engine's thread, writes it on a writer thread.

#include "collidescope/recorder/recorder.hpp"

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

/// --budget: keeps positions every `stride`th recorded frame. From the file's growth since the
/// first frames (which allocate every dataset's first chunk), it estimates what each further
/// frame costs without positions and what each kept positions frame adds, and raises the stride
/// (powers of 2, never lowered) to the least that fits the remaining frames into the budget;
/// with no room for even one more positions frame, positions stop (stride 0).
class PositionsBudget {
public:
    PositionsBudget(std::uint64_t budget, std::uint64_t frames_total) : m_budget(budget), m_total(frames_total) {}

    bool keep(std::uint64_t row) const { return m_stride != 0 && row % m_stride == 0; }
    /// After `rows_done` frames, `rows_kept` of them with positions.
    void update(std::uint64_t rows_done, std::uint64_t rows_kept, std::uint64_t positions_bytes, std::uint64_t file_bytes) {
        if (m_budget == 0 || m_stride == 0 || rows_done >= m_total) return;
        if (rows_done <= k_warmup) {
            m_base = {rows_done, rows_kept, positions_bytes, file_bytes};
            if (file_bytes < m_budget) return;  // decide on the first frames only when already over
        }
        const double remaining = static_cast<double>(m_total - rows_done);
        const double rows = static_cast<double>(std::max<std::uint64_t>(rows_done - m_base.rows, 1));
        const double growth = static_cast<double>(file_bytes - std::min(file_bytes, m_base.file));
        const double positions = static_cast<double>(positions_bytes - std::min(positions_bytes, m_base.positions));
        const double kept = static_cast<double>(rows_kept - std::min(rows_kept, m_base.kept));
        const double other = std::max(growth - positions, 0.0) / rows;
        const double per_positions = kept > 0 ? positions / kept : static_cast<double>(positions_bytes) / static_cast<double>(std::max<std::uint64_t>(rows_kept, 1));
        const double room = static_cast<double>(m_budget) - static_cast<double>(file_bytes) - remaining * other;
        if (room <= per_positions) {
            m_stride = 0;
            return;
        }
        while (m_stride < (1u << 30) && remaining / m_stride * per_positions > room) m_stride *= 2;
    }
    std::uint32_t stride() const { return m_stride; }

private:
    static constexpr std::uint64_t k_warmup = 2;  ///< frames whose growth includes first chunks
    struct Base {
        std::uint64_t rows = 0, kept = 0, positions = 0, file = 0;
    };
    std::uint64_t m_budget;
    std::uint64_t m_total;
    std::uint32_t m_stride = 1;
    Base m_base;
};

std::vector<float> to_float(const std::vector<Vec3>& vertices) {
    std::vector<float> out(vertices.size() * 3);
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (int axis = 0; axis < 3; ++axis) out[3 * v + static_cast<std::size_t>(axis)] = static_cast<float>(vertices[v][axis]);
    }
    return out;
}

}  // namespace

struct Recorder::State {
    RecorderConfig config;
    std::vector<std::string> methods = method_names();
    std::vector<std::uint64_t> revisions;  ///< last topology revision recorded, per object
    bool first = true;
    TraceFile file;
    FrameQueue queue;
    PositionsBudget budget;
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
    // Below the engine's threads: on a machine with few cores, a writer competing for a core
    // stalls the engine's parallel loops. It catches up between frames (the queue absorbs it).
    if (config.writer_nice > 0) {
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), config.writer_nice);
    }
    std::uint64_t kept = 0;
    try {
        while (std::optional<FrameRecord> record = queue.pop()) {
            const bool keep = budget.keep(summary.frames);
            file.append(*record, {keep, true});
            summary.positions_dropped += keep ? 0 : 1;
            kept += keep ? 1 : 0;
            ++summary.frames;
            if (config.budget_bytes > 0) {
                const std::uint64_t bytes = file.file_bytes();
                budget.update(summary.frames, kept, file.positions_bytes(), bytes);
            }
        }
    } catch (...) {
        std::lock_guard lock(error_mutex);
        error = std::current_exception();
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
        record.survivors = stats.gpu->survivors;
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

RecordSummary Recorder::finish() {
    State& state = *m_state;
    state.finished = true;
    state.queue.close();
    if (state.writer.joinable()) state.writer.join();
    state.rethrow_writer_error();
    state.file.close();
    TraceFile::mark_finished(state.config.path, state.summary.frames, state.budget.stride());
    state.summary.positions_stride = state.budget.stride();
    state.summary.queue_peak_bytes = state.queue.peak_bytes();
    std::error_code error;
    state.summary.file_bytes = std::filesystem::file_size(state.config.path, error);
    return state.summary;
}

}  // namespace collidescope::recorder
