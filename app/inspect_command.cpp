// `collidescope inspect`: what a recording holds (frames, objects, methods, pairs, time per
// stage, file size by group), as text or JSON.

#include "check_sinks.hpp"
#include "commands.hpp"
#include "inspect_info.hpp"
#include "size_option.hpp"

#include "collidescope/recorder/reader.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace collidescope::app {
namespace {

struct InspectOptions {
    std::string file;
    bool json = false;
};

void print_counts(const char* title, const nlohmann::ordered_json& counts) {
    std::cout << title;
    for (const auto& [name, frames] : counts.items()) std::cout << ' ' << name << " (" << frames << ")";
}

// "time: 0 s .. 2.5 s at 30 fps, clip 'Walk', up axis y": only what the file says; nothing
// for a recording without time.
void print_time(const nlohmann::ordered_json& info) {
    std::string line;
    char number[96];
    if (!info["time_range_s"].is_null()) {
        std::snprintf(number, sizeof number, "%g s .. %g s", info["time_range_s"][0].get<double>(),
                      info["time_range_s"][1].get<double>());
        line += number;
    }
    if (!info["fps"].is_null()) {
        std::snprintf(number, sizeof number, "%g fps", info["fps"].get<double>());
        line += (line.empty() ? "" : " at ") + std::string(number);
    }
    if (!info["clip"].is_null()) line += (line.empty() ? "" : ", ") + ("clip '" + info["clip"].get<std::string>() + "'");
    if (!info["up_axis"].is_null()) line += (line.empty() ? "" : ", ") + ("up axis " + info["up_axis"].get<std::string>());
    if (!line.empty()) std::cout << "time: " << line << '\n';
}

// "between frames: 59 intervals, 21 with contact, 17573 pairs touching, 7356 pass-throughs (most:
// 706, frames 28-29); first pass-through frames 19-20 at t = 0.823150: object 0 triangle 1352 with
// object 1 triangle 531; tolerance 3.2e-06 to 4.1e-06" (demo).
void print_between_frames(const nlohmann::ordered_json& b) {
    std::cout << "between frames: " << b["intervals"] << " intervals, " << b["with_contact"] << " with contact, " << b["pairs"]
              << " pairs touching, " << b["pass_throughs"] << " pass-throughs";
    if (b["most_pass_throughs"].get<std::uint64_t>() > 0) {
        std::cout << " (most: " << b["most_pass_throughs"] << ", frames " << b["most_pass_throughs_frames"][0] << "-"
                  << b["most_pass_throughs_frames"][1] << ")";
    }
    const auto& first = b["first_pass_through"];
    if (!first.is_null()) {
        char toi[32];
        std::snprintf(toi, sizeof toi, "%.6f", std::max(0.0, first["toi"].get<double>() - 1e-6));
        std::cout << "; first pass-through frames " << first["frames"][0] << "-" << first["frames"][1] << " at t = " << toi
                  << ": object " << first["pair"][0] << " triangle " << first["pair"][1] << " with object "
                  << first["pair"][2] << " triangle " << first["pair"][3];
        if (!first["resolved"].get<bool>()) std::cout << " (unresolved)";
    }
    if (b["intervals"].get<std::uint64_t>() > 0) {
        char tolerance[64];
        std::snprintf(tolerance, sizeof tolerance, "%.3g", b["tolerance_min"].get<double>());
        std::cout << "; tolerance " << tolerance;
        if (b["tolerance_max"] != b["tolerance_min"]) {
            std::snprintf(tolerance, sizeof tolerance, "%.3g", b["tolerance_max"].get<double>());
            std::cout << " to " << tolerance;
        }
    }
    if (b["unresolved"].get<std::uint64_t>() > 0) std::cout << "; " << b["unresolved"] << " pairs unresolved (query budget spent)";
    std::cout << '\n';
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
    print_time(info);
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
    if (info.contains("regions")) {
        const auto& regions = info["regions"];
        std::cout << "regions: " << regions["ids"] << " over the run, on " << regions["frames_with_regions"]
                  << " frames, at most " << regions["max_per_frame"] << " in a frame (frame " << regions["max_frame"]
                  << "); longest curve " << regions["longest_curve"].get<double>() << " (region "
                  << regions["longest_curve_region"] << ", frame " << regions["longest_curve_frame"] << ")";
        if (!regions["deepest"].is_null()) {
            std::cout << "; deepest " << regions["deepest"].get<double>() << " (region " << regions["deepest_region"]
                      << ", frame " << regions["deepest_frame"] << ")";
        }
        std::cout << "\n";
    }
    if (info.contains("between_frames")) print_between_frames(info["between_frames"]);
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
    const nlohmann::ordered_json info = inspect_info(recording);
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
