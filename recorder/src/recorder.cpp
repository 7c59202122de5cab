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

namespace collidescope::recorder {
namespace {

/// --budget: keeps positions every `stride`th recorded frame, doubling the stride whenever
/// the file, growing at its average rate so far, would pass the budget by the last frame.
class PositionsBudget {
public:
    PositionsBudget(std::uint64_t budget, std::uint64_t frames_total) : m_budget(budget), m_total(frames_total) {}

    bool keep(std::uint64_t row) const { return row % m_stride == 0; }
    /// After `rows_done` frames the file has `bytes` (of which `start_bytes` before frame 0).
    void update(std::uint64_t rows_done, std::uint64_t bytes, std::uint64_t start_bytes) {
        if (m_budget == 0 || rows_done == 0 || rows_done >= m_total) return;
        const double per_frame = static_cast<double>(bytes - std::min(bytes, start_bytes)) / static_cast<double>(rows_done);
        const double projected = static_cast<double>(bytes) + per_frame * static_cast<double>(m_total - rows_done);
        if (projected > static_cast<double>(m_budget) && m_stride < (1u << 30)) m_stride *= 2;
    }
    std::uint32_t stride() const { return m_stride; }

private:
    std::uint64_t m_budget;
    std::uint64_t m_total;
    std::uint32_t m_stride = 1;
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
    const std::uint64_t start_bytes = file.file_bytes();
    try {
        while (std::optional<FrameRecord> record = queue.pop()) {
            const bool keep = budget.keep(summary.frames);
            file.append(*record, keep);
            summary.positions_dropped += keep ? 0 : 1;
            ++summary.frames;
            if (config.budget_bytes > 0) budget.update(summary.frames, file.file_bytes(), start_bytes);
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

FrameRecord Recorder::State::copy(const FrameReport& report) {
    FrameRecord record;
    record.frame = report.frame.index;
    const auto code = std::find(methods.begin(), methods.end(), report.stats.method);
    if (code == methods.end()) throw InputError(config.path.string() + ": unknown method " + report.stats.method);
    record.method = static_cast<std::uint8_t>(code - methods.begin());
    for_each_stage(report.stats.ms, [&](const char*, double value) { record.ms.push_back(value); });
    for_each_count(report.stats.counts, [&](const char*, std::uint64_t value) { record.counts.push_back(value); });
    record.pairs.assign(report.colliding_pairs.begin(), report.colliding_pairs.end());
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
