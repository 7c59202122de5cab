// The invariants `collidescope validate` checks.

#include "collidescope/recorder/validate.hpp"

#include "collidescope/recorder/reader.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/schema.hpp"

#include <algorithm>
#include <cmath>

namespace collidescope::recorder {
namespace {

class Checker {
public:
    Checker(const Recording& recording, std::size_t max_problems)
        : m_rec(recording), m_max(max_problems), m_frames(recording.frames_complete()) {}

    ValidationReport run() {
        m_report.finished = m_rec.finished();
        m_report.frames_complete = m_frames;
        m_indices = m_rec.frame_indices();
        check_units_and_lengths();
        check_frame_indices();
        check_methods_and_times();
        check_frame_times();
        check_objects();
        check_pairs();
        check_regions();
        check_intervals();
        return std::move(m_report);
    }

private:
    void problem(const std::string& line) {
        if (m_report.problems.size() < m_max) m_report.problems.push_back(line);
        else ++m_report.problems_omitted;
    }
    static std::string frame_name(std::uint64_t row, const std::vector<std::uint32_t>& indices) {
        return "frame " + (row < indices.size() ? std::to_string(indices[row]) : "row " + std::to_string(row));
    }

    void check_units_and_lengths();
    void check_frame_indices();
    void check_methods_and_times();
    void check_frame_times();
    void check_objects();
    void check_object(std::uint32_t k);
    void check_pairs();
    void check_regions();
    void check_intervals();
    void check_interval(const RecordedInterval& interval, const std::string& where);
    /// Checks CSR offsets (frames + 1 entries used) against the flat array's rows.
    bool check_offsets(const std::string& path, const std::vector<std::uint64_t>& offsets, std::uint64_t flat_rows);
    std::uint64_t triangles_in_force(std::uint32_t object, std::uint32_t frame) const {
        const auto& topologies = m_rec.objects()[object].topologies;
        return topologies[m_rec.topology_at(object, frame)].triangle_count;
    }

    const Recording& m_rec;
    std::size_t m_max;
    std::uint64_t m_frames;
    std::vector<std::uint32_t> m_indices;
    ValidationReport m_report;
};

void Checker::check_units_and_lengths() {
    const std::string frames_prefix = std::string(schema::k_frames) + "/";
    for (const std::string& path : m_rec.dataset_paths()) {
        if (m_rec.unit_of(path).empty()) problem(path + ": no '" + schema::k_attr_unit + "' attribute");
        // Per-frame datasets all have one row per frame once the file is finished.
        const bool per_frame = path.rfind(frames_prefix, 0) == 0 || path == schema::k_interval_counts ||
                               path == schema::k_interval_ms || path == schema::k_interval_tolerance;
        if (m_report.finished && per_frame && m_rec.rows_of(path) != m_frames) {
            problem(path + ": " + std::to_string(m_rec.rows_of(path)) + " rows, but " + std::to_string(m_frames) +
                    " frames are complete");
        }
    }
}

void Checker::check_frame_indices() {
    for (std::uint64_t r = 1; r < m_indices.size(); ++r) {
        if (m_indices[r] <= m_indices[r - 1]) {
            problem(std::string(schema::k_frame_index) + ": row " + std::to_string(r) + " (frame " +
                    std::to_string(m_indices[r]) + ") does not follow frame " + std::to_string(m_indices[r - 1]));
        }
    }
}

void Checker::check_methods_and_times() {
    try {
        (void)m_rec.frame_methods();
    } catch (const InputError& error) {
        problem(error.what());
    }
    for (const Series<double>& series : m_rec.stage_ms()) {
        for (std::uint64_t r = 0; r < series.values.size(); ++r) {
            if (!std::isfinite(series.values[r]) || series.values[r] < 0) {
                problem(std::string(schema::k_frame_ms) + "/" + series.name + ": " + frame_name(r, m_indices) +
                        " has " + std::to_string(series.values[r]) + " ms");
            }
        }
    }
}

// Schema 1.4: /frames/time, when present, is in seconds, finite and never decreasing.
void Checker::check_frame_times() {
    if (!m_rec.has_frame_times()) return;
    const std::string path = schema::k_frame_time;
    if (m_rec.unit_of(path) != schema::k_unit_seconds) {
        problem(path + ": unit '" + m_rec.unit_of(path) + "', not '" + schema::k_unit_seconds + "'");
    }
    const std::vector<double> times = m_rec.frame_times();
    for (std::uint64_t r = 0; r < times.size(); ++r) {
        if (!std::isfinite(times[r])) {
            problem(path + ": " + frame_name(r, m_indices) + " has " + std::to_string(times[r]) + " s");
        } else if (r > 0 && times[r] < times[r - 1]) {
            problem(path + ": " + frame_name(r, m_indices) + " (" + std::to_string(times[r]) +
                    " s) is earlier than the frame before it (" + std::to_string(times[r - 1]) + " s)");
        }
    }
}

bool Checker::check_offsets(const std::string& path, const std::vector<std::uint64_t>& offsets, std::uint64_t flat_rows) {
    if (offsets.empty() || offsets[0] != 0) {
        problem(path + ": does not start with 0");
        return false;
    }
    for (std::uint64_t r = 0; r < m_frames && r + 1 < offsets.size(); ++r) {
        if (offsets[r + 1] < offsets[r] || offsets[r + 1] > flat_rows) {
            problem(path + ": entry " + std::to_string(r + 1) + " (" + frame_name(r, m_indices) + ") = " +
                    std::to_string(offsets[r + 1]) + " is out of range (previous " + std::to_string(offsets[r]) +
                    ", " + std::to_string(flat_rows) + " rows)");
            return false;
        }
    }
    if (m_report.finished && offsets.size() > m_frames && offsets[m_frames] != flat_rows) {
        problem(path + ": ends at " + std::to_string(offsets[m_frames]) + " but the array has " +
                std::to_string(flat_rows) + " rows");
    }
    return true;
}

void Checker::check_objects() {
    for (std::uint32_t k = 0; k < m_rec.objects().size(); ++k) check_object(k);
}

void Checker::check_object(std::uint32_t k) {
    const std::string prefix = schema::object_group(k) + "/";
    const auto& topologies = m_rec.objects()[k].topologies;
    // A file with no complete frame (a writer killed before its first) needs no topology.
    if (!m_indices.empty() && (topologies.empty() || topologies.front().from_frame > m_indices.front())) {
        problem(prefix + schema::k_topology_from_frame + ": no topology for the first frame");
        return;
    }
    for (std::size_t t = 0; t < topologies.size(); ++t) {
        if (t > 0 && topologies[t].from_frame <= topologies[t - 1].from_frame) {
            problem(prefix + schema::k_topology_from_frame + ": entry " + std::to_string(t) + " does not increase");
        }
        for (const TriIndices& tri : m_rec.triangles(k, t)) {
            if (tri[0] >= topologies[t].vertex_count || tri[1] >= topologies[t].vertex_count ||
                tri[2] >= topologies[t].vertex_count) {
                problem(prefix + schema::k_triangles + ": topology " + std::to_string(t) + " has a vertex index out of range");
                break;
            }
        }
    }
    const std::vector<std::uint64_t> offsets = m_rec.read_u64(prefix + schema::k_vertex_offsets);
    if (!check_offsets(prefix + schema::k_vertex_offsets, offsets, m_rec.rows_of(prefix + schema::k_positions))) return;
    for (std::uint64_t r = 0; r < m_frames; ++r) {
        const std::uint64_t rows = offsets[r + 1] - offsets[r];
        const std::uint32_t expected = topologies[m_rec.topology_at(k, m_indices[r])].vertex_count;
        if (rows != 0 && rows != expected) {
            problem(prefix + schema::k_positions + ": " + frame_name(r, m_indices) + " has " + std::to_string(rows) +
                    " vertices, its topology " + std::to_string(expected));
        }
    }
}

void Checker::check_pairs() {
    const std::vector<std::uint64_t> offsets = m_rec.read_u64(schema::k_pair_offsets);
    if (!check_offsets(schema::k_pair_offsets, offsets, m_rec.rows_of(schema::k_pairs))) return;
    std::vector<std::uint64_t> colliding, triangles;
    for (const Series<std::uint64_t>& series : m_rec.counts()) {
        if (series.name == "colliding_pairs") colliding = series.values;
        if (series.name == "triangles") triangles = series.values;
    }
    const auto object_count = static_cast<std::uint32_t>(m_rec.objects().size());
    for (std::uint64_t r = 0; r < m_frames; ++r) {
        const std::vector<TrianglePair> pairs = m_rec.pairs(r);
        const std::string where = std::string(schema::k_pairs) + ": " + frame_name(r, m_indices);
        if (r < colliding.size() && colliding[r] != pairs.size()) {
            problem(std::string(schema::k_frame_counts) + "/colliding_pairs: " + frame_name(r, m_indices) + " says " +
                    std::to_string(colliding[r]) + ", the offsets hold " + std::to_string(pairs.size()) + " pairs");
        }
        std::uint64_t triangle_total = 0;
        for (std::uint32_t k = 0; k < object_count; ++k) triangle_total += triangles_in_force(k, m_indices[r]);
        if (r < triangles.size() && triangles[r] != triangle_total) {
            problem(std::string(schema::k_frame_counts) + "/triangles: " + frame_name(r, m_indices) + " says " +
                    std::to_string(triangles[r]) + ", the topologies hold " + std::to_string(triangle_total));
        }
        for (std::size_t p = 0; p < pairs.size(); ++p) {
            const TrianglePair& pair = pairs[p];
            const bool objects_ok = pair.obj_a < object_count && pair.obj_b < object_count;
            if (!objects_ok || pair.tri_a >= triangles_in_force(pair.obj_a, m_indices[r]) ||
                pair.tri_b >= triangles_in_force(pair.obj_b, m_indices[r])) {
                problem(where + ", pair " + std::to_string(p) + " names a triangle that does not exist");
            } else if (make_pair_ordered(pair.obj_a, pair.tri_a, pair.obj_b, pair.tri_b) != pair ||
                       (pair.obj_a == pair.obj_b && pair.tri_a == pair.tri_b)) {
                problem(where + ", pair " + std::to_string(p) + " is not in canonical order");
            } else if (p > 0 && !(pairs[p - 1] < pair)) {
                problem(where + ", pair " + std::to_string(p) + " is not sorted after the one before");
            }
        }
    }
}

}  // namespace

ValidationReport validate_recording(const Recording& recording, std::size_t max_problems) {
    return Checker(recording, max_problems).run();
}

}  // namespace collidescope::recorder

namespace collidescope::recorder {

// /regions (1.5): every frame's regions read back through their offsets; each region's pairs
// no more than the frame's, its objects in range, its id from 1, its counts and measures
// consistent, each predecessor an id the previous frame had.
void Checker::check_regions() {
    if (!m_rec.has_regions()) return;
    const auto object_count = static_cast<std::uint32_t>(m_rec.objects().size());
    std::vector<std::uint32_t> previous_ids;
    for (std::uint64_t r = 0; r < m_frames; ++r) {
        const std::string where = std::string(schema::k_regions) + ": " + frame_name(r, m_indices);
        std::vector<RecordedRegion> regions;
        try {
            regions = m_rec.regions(r);
        } catch (const InputError& error) {
            problem(error.what());
            return;
        }
        const std::uint64_t pairs = m_rec.pairs(r).size();
        std::uint64_t region_pairs = 0;
        std::vector<std::uint32_t> ids;
        for (std::size_t k = 0; k < regions.size(); ++k) {
            const RecordedRegion& region = regions[k];
            const std::string name = where + ", region " + std::to_string(k);
            region_pairs += region.pairs;
            ids.push_back(region.id);
            if (region.id == 0) problem(name + " has id 0 (ids start at 1)");
            if (region.obj_a >= object_count || region.obj_b >= object_count) problem(name + " names an object that does not exist");
            std::uint32_t loops = 0;
            for (const RecordedRegion::Curve& curve : region.curves) loops += curve.closed ? 1 : 0;
            if (loops != region.loops) problem(name + " says " + std::to_string(region.loops) + " loops, its curves hold " + std::to_string(loops));
            if (!(region.curve_length >= 0) || !(region.coplanar_area >= 0)) problem(name + " has a negative or NaN measure");
            // The penetration measures are NaN where not defined, never negative or infinite.
            for (const double v : {region.inside_area_a, region.inside_area_b, region.depth}) {
                if (!std::isnan(v) && !(v >= 0 && std::isfinite(v))) problem(name + " has a negative or infinite inside area or depth");
            }
            for (const std::uint32_t id : region.predecessors) {
                if (std::find(previous_ids.begin(), previous_ids.end(), id) == previous_ids.end()) {
                    problem(name + " continues region " + std::to_string(id) + ", which the previous frame does not have");
                }
            }
        }
        if (region_pairs != pairs) {
            problem(where + ": the regions hold " + std::to_string(region_pairs) + " pairs, the frame " + std::to_string(pairs));
        }
        previous_ids = std::move(ids);
    }
}

// /intervals (1.7): every interval read back; its pairs sorted, unique, on triangles that exist,
// each toi in [0, 1]; its counts those of its pairs; and the pairs touching at either frame
// (/collisions, with the same self rule) among its pairs, since touching at t = 0 or t = 1 is
// touching during the interval.
void Checker::check_intervals() {
    if (!m_rec.has_intervals()) return;
    const std::vector<std::uint64_t> offsets = m_rec.read_u64(schema::k_interval_offsets);
    if (!check_offsets(schema::k_interval_offsets, offsets, m_rec.rows_of(schema::k_interval_pairs))) return;
    if (offsets.size() > 1 && offsets[1] != 0) {
        problem(std::string(schema::k_interval_offsets) + ": row 0 (which ends no interval) holds pairs");
    }
    // One toi and one flag per pair once the file is finished (a killed writer may leave them
    // shorter or longer than the pairs past the last complete frame).
    for (const char* path : {schema::k_interval_toi, schema::k_interval_flags}) {
        if (m_report.finished && m_rec.rows_of(path) != m_rec.rows_of(schema::k_interval_pairs)) {
            problem(std::string(path) + ": " + std::to_string(m_rec.rows_of(path)) + " rows, " + schema::k_interval_pairs + " " +
                    std::to_string(m_rec.rows_of(schema::k_interval_pairs)));
        }
    }
    for (std::uint64_t r = 1; r < m_frames; ++r) {
        const std::string where = std::string(schema::k_intervals) + ": frames " + std::to_string(m_indices[r - 1]) + "-" +
                                  std::to_string(m_indices[r]);
        try {
            check_interval(m_rec.interval(r), where);
        } catch (const InputError& error) {
            problem(error.what());
            return;
        }
    }
}

void Checker::check_interval(const RecordedInterval& interval, const std::string& where) {
    const auto object_count = static_cast<std::uint32_t>(m_rec.objects().size());
    const std::vector<IntervalContact>& contacts = interval.contacts;
    std::uint64_t pass_throughs = 0, unresolved = 0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const IntervalContact& c = contacts[k];
        const std::string name = where + ", pair " + std::to_string(k);
        if (k > 0 && !(contacts[k - 1].pair < c.pair)) problem(name + " is out of order or repeated");
        if (c.pair.obj_a >= object_count || c.pair.obj_b >= object_count) {
            problem(name + " names an object that does not exist");
            continue;
        }
        if (c.pair.tri_a >= triangles_in_force(c.pair.obj_a, interval.from_frame) ||
            c.pair.tri_b >= triangles_in_force(c.pair.obj_b, interval.from_frame)) {
            problem(name + " names a triangle its object does not have");
        }
        if (!(c.toi >= 0 && c.toi <= 1)) problem(name + " has a time of contact outside [0, 1]");
        pass_throughs += c.pass_through ? 1 : 0;
        unresolved += c.resolved ? 0 : 1;
    }
    const IntervalStats& s = interval.stats;
    if (s.contacts != contacts.size() || s.pass_throughs != pass_throughs || s.unresolved != unresolved) {
        problem(where + ": the counts say " + std::to_string(s.contacts) + " pairs, " + std::to_string(s.pass_throughs) +
                " pass-throughs and " + std::to_string(s.unresolved) + " unresolved; the pairs hold " +
                std::to_string(contacts.size()) + ", " + std::to_string(pass_throughs) + " and " + std::to_string(unresolved));
    }
    if (!(s.tolerance >= 0) || !std::isfinite(s.tolerance)) problem(where + ": the tolerance is negative, NaN or infinite");
    for (const std::uint64_t end : {interval.row - 1, interval.row}) {
        for (const TrianglePair& pair : m_rec.pairs(end)) {
            const auto at = std::lower_bound(contacts.begin(), contacts.end(), pair,
                                             [](const IntervalContact& c, const TrianglePair& p) { return c.pair < p; });
            if (at == contacts.end() || at->pair != pair || at->pass_through) {
                problem(where + ": the pair (" + std::to_string(pair.obj_a) + ", " + std::to_string(pair.tri_a) + ", " +
                        std::to_string(pair.obj_b) + ", " + std::to_string(pair.tri_b) + ") collides at " +
                        frame_name(end, m_indices) + " but the interval " +
                        (at != contacts.end() && at->pair == pair ? "calls it a pass-through" : "does not report it"));
                return;
            }
        }
    }
}

}  // namespace collidescope::recorder
