// What `collidescope inspect` reports about a recording, gathered once (printed as text or
// JSON by inspect_command.cpp; the recording fuzz target gathers it too, fuzz/recording_entry.cpp).

#include "inspect_info.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/stats.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <map>

namespace collidescope::app {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

// A decision code as the reader returns it: an integer 0..255 (the reader refuses others), or
// NaN when the frame's row holds none; NaN reads as 255, a code no name has ("unknown").
std::uint8_t code_of(double value) { return std::isnan(value) ? 255 : static_cast<std::uint8_t>(value); }

// Everything inspect reports, gathered once and printed as text or JSON.
// Schema 1.2: the decision system's modes, switches, actions and reasons (/frames/decision),
// and the frames that ran the hybrid framework (/frames/hybrid). NaN rows: no decision.
void add_decisions(const recorder::Recording& rec, nlohmann::ordered_json& out) {
    const auto column = [](const std::vector<recorder::Series<double>>& group, const char* name) {
        for (const auto& series : group) {
            if (series.name == name) return series.values;
        }
        return std::vector<double>{};
    };
    const auto decision = rec.frame_values("decision");
    const std::vector<double> mode = column(decision, "mode");
    const std::vector<double> action = column(decision, "action");
    const std::vector<double> reason = column(decision, "reason");
    std::map<std::string, std::uint64_t> modes, actions, reasons;
    std::uint64_t decided = 0, switches = 0;
    double previous = std::nan("");
    for (std::size_t r = 0; r < mode.size(); ++r) {
        if (std::isnan(mode[r])) continue;
        ++decided;
        ++modes["mode " + std::to_string(code_of(mode[r]))];
        ++actions[decision_action_name(r < action.size() ? code_of(action[r]) : 255)];
        ++reasons[decision_reason_name(r < reason.size() ? code_of(reason[r]) : 255)];
        if (!std::isnan(previous) && mode[r] != previous) ++switches;
        previous = mode[r];
    }
    out["decision_frames"] = decided;
    out["modes"] = modes;
    out["mode_switches"] = switches;
    out["decision_actions"] = actions;
    out["decision_reasons"] = reasons;
    const std::vector<double> wins = column(rec.frame_values("hybrid"), "predicted_hybrid_wins");
    std::uint64_t hybrid_frames = 0, predicted_wins = 0;
    for (const double w : wins) {
        hybrid_frames += std::isnan(w) ? 0 : 1;
        predicted_wins += w == 1.0 ? 1 : 0;
    }
    out["hybrid_frames"] = hybrid_frames;
    out["hybrid_predicted_wins"] = predicted_wins;
}

}  // namespace

// Schema 1.4: what the inputs said about time and orientation; null where the file does not say.
void add_time(const recorder::Recording& rec, nlohmann::ordered_json& out) {
    out["fps"] = rec.fps() > 0 ? nlohmann::ordered_json(rec.fps()) : nlohmann::ordered_json();
    out["clip"] = rec.clip().empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(rec.clip());
    out["up_axis"] = rec.up_axis() == 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(std::string(1, rec.up_axis()));
    const std::vector<double> times = rec.frame_times();
    out["time_range_s"] = times.empty() ? nlohmann::ordered_json()
                                        : nlohmann::ordered_json::array({times.front(), times.back()});
}

namespace {

// /regions (record --regions): how many regions over the run, the most in one frame, and the
// longest curve (its region and frame), and the deepest region (where a depth is defined).
nlohmann::ordered_json region_summary(const recorder::Recording& rec, const std::vector<std::uint32_t>& indices) {
    std::set<std::uint32_t> ids;
    std::uint64_t most = 0, most_frame = 0, frames_with = 0;
    double longest = 0;
    std::uint32_t longest_id = 0, longest_frame = 0;
    double deepest = -1;
    std::uint32_t deepest_id = 0, deepest_frame = 0;
    for (std::uint64_t r = 0; r < rec.frames_complete(); ++r) {
        const std::vector<recorder::RecordedRegion> regions = rec.regions(r, false);
        frames_with += regions.empty() ? 0 : 1;
        if (regions.size() > most) most = regions.size(), most_frame = indices[r];
        for (const recorder::RecordedRegion& region : regions) {
            ids.insert(region.id);
            if (region.curve_length > longest) longest = region.curve_length, longest_id = region.id, longest_frame = indices[r];
            if (region.depth > deepest) deepest = region.depth, deepest_id = region.id, deepest_frame = indices[r];
        }
    }
    nlohmann::ordered_json out{{"ids", ids.size()},           {"frames_with_regions", frames_with},
                               {"max_per_frame", most},       {"max_frame", most_frame},
                               {"longest_curve", longest},    {"longest_curve_region", longest_id},
                               {"longest_curve_frame", longest_frame}};
    // null: no region had a depth (no closed object, self-contact only, or a 1.5 recording)
    out["deepest"] = deepest >= 0 ? nlohmann::ordered_json(deepest) : nlohmann::ordered_json();
    out["deepest_region"] = deepest_id;
    out["deepest_frame"] = deepest_frame;
    return out;
}

// /intervals (record --between-frames): the intervals' totals, the one with the most
// pass-throughs, and the first pass-through of the run (the first interval with any; its
// earliest resolved one, else its earliest: interval, pair and time).
nlohmann::ordered_json interval_summary(const recorder::Recording& rec) {
    std::uint64_t intervals = 0, with_contact = 0, pairs = 0, pass_throughs = 0, unresolved = 0, most = 0, most_row = 0,
                  first_row = 0;
    double ms = 0, tolerance_min = 0, tolerance_max = 0;
    const std::vector<IntervalStats> all = rec.interval_stats();
    for (std::uint64_t r = 1; r < all.size(); ++r) {
        const IntervalStats& s = all[r];
        tolerance_min = intervals == 0 ? s.tolerance : std::min(tolerance_min, s.tolerance);
        tolerance_max = intervals == 0 ? s.tolerance : std::max(tolerance_max, s.tolerance);
        ++intervals;
        with_contact += s.contacts > 0 ? 1 : 0;
        pairs += s.contacts, pass_throughs += s.pass_throughs, unresolved += s.unresolved, ms += s.ms;
        if (s.pass_throughs > most) most = s.pass_throughs, most_row = r;
        if (first_row == 0 && s.pass_throughs > 0) first_row = r;
    }
    nlohmann::ordered_json out{{"intervals", intervals},         {"with_contact", with_contact},
                               {"pairs", pairs},                 {"pass_throughs", pass_throughs},
                               {"unresolved", unresolved},       {"total_ms", ms},
                               {"tolerance_min", tolerance_min}, {"tolerance_max", tolerance_max}};
    const auto frames_of = [&](std::uint64_t row) {
        const recorder::RecordedInterval i = rec.interval(row, false);
        return nlohmann::ordered_json::array({i.from_frame, i.to_frame});
    };
    out["most_pass_throughs"] = most;
    out["most_pass_throughs_frames"] = most > 0 ? frames_of(most_row) : nlohmann::ordered_json();
    // The run's first pass-through: the earliest of the first interval that has any.
    out["first_pass_through"] = nlohmann::ordered_json();
    if (first_row > 0) {
        const recorder::RecordedInterval i = rec.interval(first_row);
        // Resolved ones first (their time is proven within the tolerance), as replay's moments.
        const IntervalContact* first = nullptr;
        for (const IntervalContact& c : i.contacts) {
            if (!c.pass_through) continue;
            const bool earlier = first == nullptr || (c.resolved && !first->resolved) ||
                                 (c.resolved == first->resolved && c.toi < first->toi);
            if (earlier) first = &c;
        }
        if (first == nullptr) {
            throw InputError(rec.path() + ": " + recorder::schema::k_interval_flags + ": frames " + std::to_string(i.from_frame) + "-" +
                             std::to_string(i.to_frame) + ": the counts say " + std::to_string(i.stats.pass_throughs) +
                             " pass-throughs, the flags none (corrupt recording; validate says more)");
        }
        out["first_pass_through"] = {{"frames", {i.from_frame, i.to_frame}},
                                     {"pair", {first->pair.obj_a, first->pair.tri_a, first->pair.obj_b, first->pair.tri_b}},
                                     {"toi", first->toi},
                                     {"resolved", first->resolved}};
    }
    return out;
}

}  // namespace

nlohmann::ordered_json inspect_info(const recorder::Recording& rec) {
    nlohmann::ordered_json out;
    out["file"] = rec.path();
    out["schema_version"] = std::to_string(rec.version_major()) + "." + std::to_string(rec.version_minor());
    out["finished"] = rec.finished();
    out["interrupted"] = rec.interrupted();
    out["partial"] = !rec.partial_reason().empty();
    out["partial_reason"] = rec.partial_reason();
    out["frames"] = rec.frames_complete();
    nlohmann::ordered_json metadata = nlohmann::ordered_json::object();
    for (const auto& [name, value] : rec.metadata()) metadata[name] = value;
    out["metadata"] = metadata;
    const std::vector<std::uint32_t> indices = rec.frame_indices();
    out["first_frame"] = indices.empty() ? 0 : indices.front();
    out["last_frame"] = indices.empty() ? 0 : indices.back();
    add_time(rec, out);
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (const recorder::ObjectInfo& object : rec.objects()) {
        nlohmann::ordered_json topologies = nlohmann::ordered_json::array();
        for (const recorder::TopologyInfo& t : object.topologies) {
            topologies.push_back({{"from_frame", t.from_frame}, {"triangles", t.triangle_count}, {"vertices", t.vertex_count}});
        }
        objects.push_back({{"name", object.name}, {"topologies", topologies}});
    }
    out["objects"] = objects;
    const std::vector<std::string> methods = rec.frame_methods();
    std::map<std::string, std::uint64_t> frames_per_method;
    std::uint64_t switches = 0;
    for (std::size_t r = 0; r < methods.size(); ++r) {
        ++frames_per_method[methods[r]];
        if (r > 0 && methods[r] != methods[r - 1]) ++switches;
    }
    out["methods"] = frames_per_method;
    out["method_switches"] = switches;
    add_decisions(rec, out);
    const std::vector<std::uint64_t> pair_counts = rec.pair_counts();
    std::uint64_t total = 0, colliding_frames = 0, max_pairs = 0, max_frame = 0;
    for (std::size_t r = 0; r < pair_counts.size(); ++r) {
        total += pair_counts[r];
        colliding_frames += pair_counts[r] > 0 ? 1 : 0;
        if (pair_counts[r] > max_pairs) {
            max_pairs = pair_counts[r];
            max_frame = indices[r];
        }
    }
    out["pairs"] = {{"total", total}, {"frames_with_collisions", colliding_frames}, {"max_per_frame", max_pairs},
                    {"max_frame", max_frame}};
    if (rec.has_regions()) out["regions"] = region_summary(rec, indices);
    if (rec.has_intervals()) out["between_frames"] = interval_summary(rec);
    nlohmann::ordered_json stages = nlohmann::ordered_json::object();
    for (const recorder::Series<double>& s : rec.stage_ms()) {
        double sum = 0;
        for (const double v : s.values) sum += v;
        stages[s.name] = {{"median_ms", median(s.values)}, {"total_ms", sum}};
    }
    out["stages"] = stages;
    std::error_code error;
    out["file_bytes"] = std::filesystem::file_size(rec.path(), error);
    std::map<std::string, std::uint64_t> by_group;
    for (const std::string& path : rec.dataset_paths()) {
        by_group[path.substr(0, path.find('/', 1))] += rec.storage_of(path);
    }
    out["bytes_by_group"] = by_group;
    return out;
}

}  // namespace collidescope::app
