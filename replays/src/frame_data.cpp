// Reading a recording for replay: the series at once, one frame's geometry and state on demand.

#include "frame_data.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::replays {

double value_of(const NamedValues& values, const std::string& name) {
    for (const auto& [key, value] : values) {
        if (key == name) return value;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

int frame_mode(const std::string& method, const NamedValues& decision) {
    const double mode = value_of(decision, "mode");
    if (std::isfinite(mode)) return int(mode);
    if (method == "aabb") return 1;
    if (method == "gpu" || method == "gpu-naive") return 2;
    if (method == "hybrid") return 3;
    return 0;
}

RecordingData::RecordingData(const std::filesystem::path& path)
    : m_path(path.string()), m_recording(path), m_metadata(m_recording.metadata()),
      m_indices(m_recording.frame_indices()), m_methods(m_recording.frame_methods()),
      m_stage_ms(m_recording.stage_ms()), m_counts(m_recording.counts()),
      m_gpu(m_recording.frame_values("gpu")), m_decision(m_recording.frame_values("decision")),
      m_aabb(m_recording.frame_values("aabb")), m_hybrid(m_recording.frame_values("hybrid")),
      m_pair_counts(m_recording.pair_counts()) {
    const std::uint64_t frames = m_indices.size();
    m_totals.assign(frames, 0.0);
    for (const recorder::Series<double>& series : m_stage_ms) {
        if (series.name == "total") m_totals.assign(series.values.begin(), series.values.end());
    }
    m_modes.resize(frames);
    for (std::uint64_t row = 0; row < frames; ++row) m_modes[row] = frame_mode(m_methods[row], row_of(m_decision, row));
    m_lives = region_lives(m_recording, frames);
    const std::vector<IntervalStats> intervals = m_recording.interval_stats();
    for (std::uint64_t row = 1; row < intervals.size() && row < frames; ++row) {
        if (intervals[row].pass_throughs > 0) m_pass_through_rows.push_back(row);
    }
}

std::vector<std::string> RecordingData::object_names() const {
    std::vector<std::string> names;
    for (const recorder::ObjectInfo& object : m_recording.objects()) names.push_back(object.name);
    return names;
}

std::string RecordingData::attribute(const std::string& name) const {
    for (const auto& [key, value] : m_metadata) {
        if (key == name) return value;
    }
    return "";
}

std::vector<std::uint64_t> RecordingData::rows_in(std::uint32_t begin, std::uint32_t end) const {
    std::vector<std::uint64_t> rows;
    for (std::uint64_t row = 0; row < m_indices.size(); ++row) {
        if (m_indices[row] >= begin && m_indices[row] < end) rows.push_back(row);
    }
    return rows;
}

Bounds RecordingData::bounds(const std::vector<std::uint64_t>& rows) {
    Bounds bounds;
    for (const std::uint64_t row : rows) {
        for (std::uint32_t object = 0; object < object_count(); ++object) {
            const std::vector<float> xyz = m_recording.positions(object, row);
            for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) bounds.add(xyz[i], xyz[i + 1], xyz[i + 2]);
        }
    }
    return bounds;
}

std::vector<Bounds> RecordingData::collision_bounds(const std::vector<std::uint64_t>& rows) {
    std::vector<Bounds> out(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::uint64_t row = rows[i];
        if (m_pair_counts[row] == 0) continue;
        std::map<std::uint32_t, std::vector<std::uint32_t>> triangles;  // per object, colliding ones
        for (const TrianglePair& pair : m_recording.pairs(row)) {
            triangles[pair.obj_a].push_back(pair.tri_a);
            triangles[pair.obj_b].push_back(pair.tri_b);
        }
        for (const auto& [object, list] : triangles) {
            if (object >= object_count()) continue;  // load() names the bad pair
            const std::vector<float> xyz = m_recording.positions(object, row);
            const auto faces = topology(object, m_recording.topology_at(object, m_indices[row]));
            for (const std::uint32_t t : list) {
                if (t >= faces->size()) continue;
                for (const std::uint32_t v : (*faces)[t]) {
                    if (3 * std::size_t(v) + 2 < xyz.size()) out[i].add(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
                }
            }
        }
    }
    return out;
}

NamedValues RecordingData::row_of(const std::vector<recorder::Series<double>>& series, std::uint64_t row) {
    NamedValues values;
    // A group whose first value is NaN was not set on this frame (the method does not report it).
    if (series.empty() || row >= series.front().values.size() || std::isnan(series.front().values[row])) return values;
    for (const recorder::Series<double>& one : series) values.emplace_back(one.name, one.values[row]);
    return values;
}

std::shared_ptr<const std::vector<TriIndices>> RecordingData::topology(std::uint32_t object, std::size_t index) {
    auto& cached = m_topologies[{object, index}];
    if (!cached) cached = std::make_shared<const std::vector<TriIndices>>(m_recording.triangles(object, index));
    return cached;
}

FrameData RecordingData::load(std::uint64_t row, std::uint64_t ordinal) {
    FrameData data;
    data.row = row;
    data.frame = m_indices[row];
    data.ordinal = ordinal;
    data.method = m_methods[row];
    for (const recorder::Series<double>& series : m_stage_ms) data.stage_ms.emplace_back(series.name, series.values[row]);
    for (const recorder::Series<std::uint64_t>& series : m_counts) {
        data.counts.emplace_back(series.name, double(series.values[row]));
    }
    data.gpu = row_of(m_gpu, row);
    data.decision = row_of(m_decision, row);
    data.aabb = row_of(m_aabb, row);
    data.hybrid = row_of(m_hybrid, row);
    data.pcs_recorded = !data.gpu.empty();
    if (data.pcs_recorded) {
        data.passes = m_recording.gpu_passes(row);
        data.depth_images = m_recording.depth_images(row);
    }
    const std::uint8_t base = data.pcs_recorded ? k_state_culled : k_state_plain;
    data.objects.resize(object_count());
    for (std::uint32_t object = 0; object < object_count(); ++object) {
        ObjectFrame& out = data.objects[object];
        out.topology = m_recording.topology_at(object, data.frame);
        out.triangles = topology(object, out.topology);
        out.positions = m_recording.positions(object, row);
        if (out.positions.empty() && !out.triangles->empty()) data.positions_dropped = true;
        out.states.assign(out.triangles->size(), base);
    }
    auto mark = [&](std::uint32_t object, std::uint32_t triangle, std::uint8_t state) {
        if (object >= data.objects.size() || triangle >= data.objects[object].states.size()) {
            throw InputError(m_path + ": frame " + std::to_string(data.frame) + ": object " + std::to_string(object) +
                             " triangle " + std::to_string(triangle) + " out of range");
        }
        data.objects[object].states[triangle] = std::max(data.objects[object].states[triangle], state);
    };
    if (data.pcs_recorded) {
        for (const auto& [object, triangle] : m_recording.survivors(row)) mark(object, triangle, k_state_pcs);
    }
    data.colliding = m_recording.pairs(row);
    if (m_recording.has_regions()) data.regions = m_recording.regions(row);
    for (const TrianglePair& pair : data.colliding) {
        mark(pair.obj_a, pair.tri_a, k_state_colliding);
        mark(pair.obj_b, pair.tri_b, k_state_colliding);
    }
    return data;
}

FrameData RecordingData::load_moment(std::uint64_t row, std::uint64_t ordinal) {
    FrameData data = load(row - 1, ordinal);
    const recorder::RecordedInterval interval = m_recording.interval(row);
    ContactMoment moment;
    moment.to_frame = interval.to_frame;
    moment.contacts = interval.stats.contacts;
    moment.pass_throughs = interval.stats.pass_throughs;
    // The earliest resolved pass-through (its time proven within the tolerance); the earliest
    // unresolved one only when the interval has no other.
    moment.resolved = std::any_of(interval.contacts.begin(), interval.contacts.end(),
                                  [](const IntervalContact& c) { return c.pass_through && c.resolved; });
    const auto counts = [&](const IntervalContact& c) { return c.pass_through && c.resolved == moment.resolved; };
    moment.toi = 2;
    for (const IntervalContact& c : interval.contacts) {
        if (counts(c)) moment.toi = std::min(moment.toi, c.toi);
    }
    if (moment.toi > 1) {
        throw InputError(m_path + ": frames " + std::to_string(interval.from_frame) + "-" + std::to_string(interval.to_frame) +
                         ": no pass-through in this interval");
    }
    for (const IntervalContact& c : interval.contacts) {
        if (counts(c) && c.toi == moment.toi) moment.first.push_back(c.pair);
    }
    // Only the moment's pairs are marked: the culling state, pairs and regions loaded are the
    // first frame's, not the moment's.
    data.pcs_recorded = false;
    data.passes.clear();
    data.depth_images.clear();
    data.regions.clear();
    data.colliding = moment.first;
    const auto t = static_cast<float>(moment.toi);
    for (std::uint32_t object = 0; object < object_count(); ++object) {
        ObjectFrame& out = data.objects[object];
        out.states.assign(out.triangles->size(), k_state_plain);
        const std::vector<float> next = m_recording.positions(object, row);
        if (next.size() != out.positions.size()) {  // --budget dropped one of the two frames
            data.positions_dropped = data.positions_dropped || !out.triangles->empty();
            out.positions.clear();
            continue;
        }
        for (std::size_t i = 0; i < next.size(); ++i) out.positions[i] += t * (next[i] - out.positions[i]);
    }
    // The first pair's centre: the mean of its six corners at the moment.
    double sum[3] = {0, 0, 0};
    int corners = 0;
    for (const TrianglePair& pair : moment.first) {
        for (const auto& [object, triangle] : {std::pair{pair.obj_a, pair.tri_a}, std::pair{pair.obj_b, pair.tri_b}}) {
            if (object >= data.objects.size() || triangle >= data.objects[object].states.size()) {
                throw InputError(m_path + ": frames " + std::to_string(interval.from_frame) + "-" +
                                 std::to_string(interval.to_frame) + ": object " + std::to_string(object) + " triangle " +
                                 std::to_string(triangle) + " out of range");
            }
            ObjectFrame& out = data.objects[object];
            out.states[triangle] = k_state_colliding;
            if (out.positions.empty() || &pair != &moment.first.front()) continue;
            for (const std::uint32_t v : (*out.triangles)[triangle]) {
                if (3 * std::size_t(v) + 2 >= out.positions.size()) continue;  // validate names it
                for (int k = 0; k < 3; ++k) {
                    moment.corners[corners][k] = out.positions[3 * std::size_t(v) + k];
                    sum[k] += moment.corners[corners][k];
                }
                ++corners;
            }
        }
    }
    if (corners == 6) {
        for (int k = 0; k < 3; ++k) moment.point[k] = sum[k] / 6.0;
        moment.point_known = true;
    }
    data.moment = std::move(moment);
    return data;
}

}  // namespace collidescope::replays
