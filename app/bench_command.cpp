// `collidescope bench`: every method on every data set, frames in memory, import excluded;
// frames.csv, summary.csv, a printed table, a plot per scene and an index.html; and the check
// that every method returned exactly the same pairs on every frame.

#include "aabb_cli_options.hpp"
#include "number_checks.hpp"
#include "bench_report.hpp"
#include "bench_run.hpp"
#include "commands.hpp"
#include "frame_range.hpp"
#include "gpu_cli_options.hpp"
#include "progress.hpp"
#include "scene_input.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

namespace collidescope::app {
namespace {

struct BenchOptions {
    std::vector<std::string> scenes = {"A", "B", "C", "D", "E1", "E2", "E3", "E4"};
    std::string preset = "default";   ///< for scenes named without :PRESET
    std::vector<std::string> methods;  ///< empty = every method (brute on small presets only)
    int repeat = 3;
    int threads = 0;
    std::string frames;                ///< "" = every frame of every scene
    std::string output;
    GpuOptions gpu;
    AabbOptions aabb;
};

std::string with_preset(const std::string& scene, const std::string& preset) {
    return scene.find(':') == std::string::npos ? scene + ":" + preset : scene;
}

// The methods to run on `scene`: those asked for, or every method, except that the references
// (brute: quadratic; gpu-naive: one occlusion query per triangle) run by default only on small
// presets.
std::vector<std::string> methods_for(const BenchOptions& options, const Scene& scene,
                                     const std::vector<std::string>& available) {
    if (!options.methods.empty()) return options.methods;
    std::vector<std::string> methods;
    for (const std::string& method : available) {
        if ((method == "brute" || method == "gpu-naive") && scene.preset != "small") continue;
        if (method == "adaptive") continue;  // the same as adaptive-<its policy>, which run anyway
        methods.push_back(method);
    }
    return methods;
}

// Every method this machine can run; the others are skipped with their reason (a method named
// with --methods is not skipped: it fails the run with its reason).
std::vector<std::string> available_methods(const BenchOptions& options, Progress& progress) {
    std::vector<std::string> available;
    for (const std::string& method : method_names()) {
        try {
            PipelineConfig config;
            config.gpu = gpu_config(options.gpu);
            make_method(method, config);
            available.push_back(method);
        } catch (const UnavailableError& error) {
            progress.log("skipping method " + method + ": " + error.what());
        }
    }
    return available;
}

std::string settings_line(const BenchOptions& options) {
    const unsigned hardware = std::thread::hardware_concurrency();
    return "repeat " + std::to_string(options.repeat) + ", threads " +
           (options.threads == 0 ? "all (" + std::to_string(hardware) + ")" : std::to_string(options.threads)) +
           ", frames " + (options.frames.empty() ? "all" : options.frames) +
           "; frame generation and import are not timed";
}

std::string mismatch_line(const BenchScene& scene, const BenchMismatch& m) {
    return "scene " + scene.name + ":" + scene.preset + " frame " + std::to_string(m.frame) + ": method " +
           m.method + " misses " + std::to_string(m.missing) + " and adds " + std::to_string(m.extra) +
           " pairs of " + m.reference;
}

void write_reports(const std::filesystem::path& directory, const std::vector<BenchScene>& results,
                   const std::vector<BenchSummary>& rows, const BenchOptions& options) {
    write_frames_csv(directory / "frames.csv", results);
    write_summary_csv(directory / "summary.csv", rows);
    draw_plots(directory);
    write_index_html(directory / "index.html", results, rows, settings_line(options));
}

int run_bench(const BenchOptions& options) {
    const std::filesystem::path directory(options.output);
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) throw InputError(directory.string() + ": cannot create the output folder: " + error.message());

    Progress setup(0);
    const std::vector<std::string> available =
        options.methods.empty() ? available_methods(options, setup) : options.methods;
    std::vector<Scene> scenes;
    std::vector<BenchPlan> plans;
    std::uint64_t steps = 0;
    for (const std::string& name : options.scenes) {
        Scene scene = make_builtin_scene(with_preset(name, options.preset));
        const FrameRange range = parse_frame_range(options.frames, scene.source->frame_count());
        plans.push_back({methods_for(options, scene, available), range.begin, range.end, options.repeat,
                         options.threads, scene.self_collision, gpu_config(options.gpu),
                         options.aabb});
        steps += std::uint64_t{range.end - range.begin} * static_cast<std::uint64_t>(options.repeat) *
                 plans.back().methods.size();
        scenes.push_back(std::move(scene));
    }

    Progress progress(steps);
    std::vector<BenchScene> results;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        if (plans[i].methods.empty()) {
            progress.log("scene " + scenes[i].name + ":" + scenes[i].preset +
                         ": no method to run (brute and gpu-naive run only on small presets unless --methods names them)");
            continue;
        }
        results.push_back(run_bench_scene(scenes[i], plans[i], [&] { progress.advance(); }));
    }
    progress.finish();

    const std::vector<BenchSummary> rows = summarize(results);
    write_reports(directory, results, rows, options);
    print_table(std::cout, rows);
    const std::string analysis = hybrid_analysis(results);
    std::cout << analysis;
    if (!analysis.empty()) write_text_file(directory / "hybrid_analysis.txt", analysis);
    std::cout.flush();

    std::uint64_t frames_checked = 0;
    std::vector<std::string> mismatches;
    for (const BenchScene& scene : results) {
        frames_checked += scene.frames.size() / std::max<std::size_t>(1, scene.methods.size());
        for (const BenchMismatch& m : scene.mismatches) mismatches.push_back(mismatch_line(scene, m));
    }
    for (const std::string& line : mismatches) progress.log("mismatch: " + line);
    if (!mismatches.empty()) {
        throw std::runtime_error(std::to_string(mismatches.size()) +
                                 " frames where methods returned different pairs; first: " + mismatches.front());
    }
    progress.log("all methods returned identical pairs on every frame (" + std::to_string(frames_checked) +
                 " frames checked); wrote " + (directory / "index.html").string());
    return 0;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* command = app.add_subcommand(
        "bench", "Run every method on every data set; CSVs, plots, a table, and a check that all "
                 "methods agree");
    command->footer(
        "Writes DIR/frames.csv (per scene, method and frame: every stage's ms and every count),\n"
        "DIR/summary.csv (per scene and method: median and total ms, ratio to the fastest),\n"
        "DIR/time_<scene>_<preset>.svg (time per frame per method, drawn by plot_bench.py with\n"
        "Debian's python3-matplotlib) and DIR/index.html; prints the\n"
        "summary table on stdout. Each frame's time is the median over --repeat runs of the whole\n"
        "animation (fresh pipelines each run; each method runs the animation alone, one method after\n"
        "another). Frames are generated before the clock starts.\n"
        "Exit codes: 0 all methods returned the same pairs on every frame, 2 a mismatch or error.");
    command->add_option("--scenes", options->scenes, "Built-in scenes, NAME[:PRESET] (" +
                        builtin_scene_list() + ")")
        ->delimiter(',')
        ->capture_default_str();
    command->add_option("--preset", options->preset, "Preset for scenes named without one (small, default, large)")
        ->capture_default_str();
    command->add_option("--methods", options->methods,
                        "Methods to compare (default: all; brute and gpu-naive only on small presets unless named)")
        ->delimiter(',')
        ->check(CLI::IsMember(method_names()));
    command->add_option("--repeat", options->repeat, "Runs per method; each frame reports the median")
        ->check(whole_number(1, 1000, "of runs per method"))
        ->capture_default_str();
    command->add_option("--threads", options->threads, "Worker threads (0 = all hardware threads)")
        ->check(whole_number(0, 1024, "of worker threads (0: all hardware threads)"))
        ->capture_default_str();
    command->add_option("--frames", options->frames, "Frames of every scene: A:B (half-open), A:, :B or N")
        ->type_name("A:B");
    command->add_option("-o,--output", options->output, "Output folder (created when missing)")
        ->type_name("DIR")
        ->required();
    add_gpu_options(*command, options->gpu);
    add_aabb_options(*command, options->aabb);
    return {command, [options] { return run_bench(*options); }};
}

}  // namespace collidescope::app
