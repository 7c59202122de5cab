// `collidescope inspect`: what a recording holds (frames, objects, methods, pairs, time per
// stage, file size by group), as text or JSON.

#include "commands.hpp"
#include "size_option.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/stats.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace collidescope::app {
namespace {

struct InspectOptions {
    std::string file;
    bool json = false;
};

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

std::string format_ms(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", ms);
    return text;
}

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
        ++modes["mode " + std::to_string(static_cast<int>(mode[r]))];
        ++actions[decision_action_name(static_cast<std::uint8_t>(action[r]))];
        ++reasons[decision_reason_name(static_cast<std::uint8_t>(reason[r]))];
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

nlohmann::ordered_json gather(const recorder::Recording& rec) {
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

void print_counts(const char* title, const nlohmann::ordered_json& counts) {
    std::cout << title;
    for (const auto& [name, frames] : counts.items()) std::cout << ' ' << name << " (" << frames << ")";
}

void print_text(const nlohmann::ordered_json& info) {
    const auto& meta = info["metadata"];
    const auto text = [&](const char* key) { return meta.contains(key) ? meta[key].get<std::string>() : std::string(); };
    std::cout << info["file"].get<std::string>() << ": collidescope recording, schema " << info["schema_version"].get<std::string>()
              << ", " << (info["partial"].get<bool>() ? "PARTIAL: " + info["partial_reason"].get<std::string>() : "complete")
              << ", "
              << info["frames"] << " frames complete (scene frames " << info["first_frame"] << ".." << info["last_frame"] << ")\n";
    std::cout << "scene '" << text("scene") << "' preset '" << text("scene_preset") << "' seed " << text("scene_seed")
              << ", method " << text("method") << ", self-collision " << (text("self_collision") == "1" ? "on" : "off")
              << ", threads " << text("threads") << ", collidescope " << text("tool_version") << " (git "
              << text("git_revision") << ")\n";
    std::cout << "objects: " << info["objects"].size() << '\n';
    for (std::size_t k = 0; k < info["objects"].size(); ++k) {
        const auto& object = info["objects"][k];
        const auto& first = object["topologies"].empty() ? nlohmann::ordered_json{{"triangles", 0}, {"vertices", 0}}
                                                          : object["topologies"][0];
        std::cout << "  " << k << " " << object["name"].get<std::string>() << ": " << first["triangles"] << " triangles, "
                  << first["vertices"] << " vertices, " << object["topologies"].size() << " topolog"
                  << (object["topologies"].size() == 1 ? "y" : "ies") << '\n';
    }
    std::cout << "methods:";
    for (const auto& [name, frames] : info["methods"].items()) std::cout << ' ' << name << " (" << frames << " frames)";
    std::cout << ", " << info["method_switches"] << " switches\n";
    if (info["decision_frames"].get<std::uint64_t>() > 0) {
        print_counts("modes (decision system):", info["modes"]);
        std::cout << ", " << info["mode_switches"] << " switches\n";
        print_counts("  actions:", info["decision_actions"]);
        print_counts("; reasons:", info["decision_reasons"]);
        std::cout << '\n';
    }
    if (info["hybrid_frames"].get<std::uint64_t>() > 0) {
        std::cout << "hybrid framework: " << info["hybrid_frames"] << " frames, Inequality 4.16 predicted it wins on "
                  << info["hybrid_predicted_wins"] << '\n';
    }
    const auto& pairs = info["pairs"];
    std::cout << "pairs: " << pairs["total"] << " colliding pairs, " << pairs["frames_with_collisions"]
              << " frames with collisions, at most " << pairs["max_per_frame"] << " (frame " << pairs["max_frame"] << ")\n";
    std::cout << "time per stage (ms):          median        total\n";
    for (const auto& [name, stage] : info["stages"].items()) {
        char line[128];
        std::snprintf(line, sizeof line, "  %-20s %12s %12s\n", name.c_str(), format_ms(stage["median_ms"].get<double>()).c_str(),
                      format_ms(stage["total_ms"].get<double>()).c_str());
        std::cout << line;
    }
    std::cout << "file size: " << format_size(info["file_bytes"].get<std::uint64_t>()) << "; datasets by group:";
    for (const auto& [group, bytes] : info["bytes_by_group"].items()) std::cout << ' ' << group << ' ' << format_size(bytes.get<std::uint64_t>());
    std::cout << '\n';
}

int run_inspect(const InspectOptions& options) {
    const recorder::Recording recording(options.file);
    const nlohmann::ordered_json info = gather(recording);
    if (options.json) std::cout << info.dump(2) << '\n';
    else print_text(info);
    return 0;
}

}  // namespace

Command add_inspect_command(CLI::App& app) {
    auto options = std::make_shared<InspectOptions>();
    CLI::App* inspect = app.add_subcommand("inspect", "Summarise a recording: frames, objects, methods, pairs, times, sizes");
    inspect->add_option("file", options->file, "A recording (collidescope record -o FILE)")->required()->type_name("FILE.h5");
    inspect->add_flag("--json", options->json, "Print JSON instead of text");
    inspect->footer("Exit codes: 0 printed, 2 error (not a recording, corrupt, newer schema).");
    return {inspect, [options] { return run_inspect(*options); }};
}

}  // namespace collidescope::app
