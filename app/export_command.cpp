// `collidescope export`: writes a built-in scene as binary PLY frame sequences plus a
// scene.json manifest (the format `check` reads), so any tool can read exactly its frames.

#include "commands.hpp"
#include "frame_range.hpp"
#include "progress.hpp"
#include "scene_input.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

namespace collidescope::app {
namespace {

struct ExportOptions {
    std::string scene;        ///< NAME[:PRESET]
    std::string output;       ///< directory, created when missing
    std::string frames;       ///< "" = every frame
    bool quiet = false;
};

// A file-name stem for each object: its name with anything but [A-Za-z0-9_-] replaced, made
// unique by its index where two objects would share a stem.
std::vector<std::string> file_stems(const FrameSource& source) {
    std::vector<std::string> stems;
    std::set<std::string> used;
    for (std::uint32_t object = 0; object < source.object_count(); ++object) {
        std::string stem = source.object_name(object);
        for (char& c : stem) {
            const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
            if (!keep) c = '_';
        }
        if (stem.empty() || used.contains(stem)) stem += "_" + std::to_string(object);
        used.insert(stem);
        stems.push_back(stem);
    }
    return stems;
}

// True when every coordinate is a float32 value, so a float PLY keeps it exactly.
bool all_float32(const std::vector<Vec3>& vertices) {
    for (const Vec3& v : vertices) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!is_float32(v[axis])) return false;
        }
    }
    return true;
}

std::string frame_file(const std::string& stem, std::uint32_t frame) {
    char number[16];
    std::snprintf(number, sizeof number, "%04u", frame);
    return stem + "." + number + ".ply";
}

void write_object_frame(const std::filesystem::path& file, const ObjectFrame& object) {
    const MeshData mesh{object.vertices.to_vector(), object.topology->triangles};
    write_ply(file, mesh, !all_float32(mesh.vertices));
}

void write_manifest(const std::filesystem::path& directory, const Scene& scene,
                    const std::vector<std::string>& stems, std::uint32_t frames) {
    nlohmann::json objects = nlohmann::json::array();
    for (std::uint32_t object = 0; object < stems.size(); ++object) {
        objects.push_back({{"name", scene.source->object_name(object)},
                           {"pattern", stems[object] + ".%04d.ply"}});
    }
    const nlohmann::json manifest = {{"name", scene.name},
                                     {"preset", scene.preset},
                                     {"seed", scene.seed},
                                     {"frames", frames},
                                     {"self", scene.self_collision},
                                     {"objects", objects}};
    const std::filesystem::path file = directory / "scene.json";
    std::ofstream out(file);
    out << manifest.dump(2) << '\n';
    if (!out.flush()) throw InputError(file.string() + ": cannot write the manifest");
}

int run_export(const ExportOptions& options) {
    const Scene scene = make_builtin_scene(options.scene);
    const FrameRange range = parse_frame_range(options.frames, scene.source->frame_count());
    const std::filesystem::path directory(options.output);
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) throw InputError(directory.string() + ": cannot create the output folder: " + error.message());

    const std::vector<std::string> stems = file_stems(*scene.source);
    Progress progress(range.end - range.begin);
    std::uint64_t triangles = 0;
    for (std::uint32_t f = range.begin; f < range.end; ++f) {
        const Frame frame = scene.source->frame(f);
        for (std::uint32_t object = 0; object < stems.size(); ++object) {
            // Files are numbered from 0 whatever the first exported frame, so the manifest's
            // frame 0 is the first frame written.
            write_object_frame(directory / frame_file(stems[object], f - range.begin), frame.objects[object]);
            if (f == range.begin) triangles += frame.objects[object].triangle_count();
        }
        progress.advance();
    }
    write_manifest(directory, scene, stems, range.end - range.begin);
    progress.finish();
    if (!options.quiet) {
        progress.log("exported scene '" + scene.name + "' (" + scene.preset + "): " +
                     std::to_string(stems.size()) + " objects, " + std::to_string(triangles) +
                     " triangles in the first frame, frames " + std::to_string(range.begin) + ".." +
                     std::to_string(range.end - 1) + " to " + (directory / "scene.json").string());
    }
    return 0;
}

}  // namespace

Command add_export_command(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* command = app.add_subcommand(
        "export", "Write a built-in scene as binary PLY frame sequences plus a scene.json manifest");
    command->footer(
        "Writes DIR/<object>.%04d.ply per object and frame (float32 coordinates, or double where a\n"
        "coordinate is not a float32 value, so the files hold exactly the scene's values) and\n"
        "DIR/scene.json, which `collidescope check DIR/scene.json` reads back. With --frames A:B\n"
        "the files are numbered from 0 at frame A.");
    command->add_option("scene", options->scene,
                        "The built-in scene, NAME[:PRESET] (" + builtin_scene_list() + ")")
        ->type_name("NAME[:PRESET]")
        ->required();
    command->add_option("-o,--output", options->output, "Output folder (created when missing)")
        ->type_name("DIR")
        ->required();
    command->add_option("--frames", options->frames, "Frames to export: A:B (half-open), A:, :B or N")
        ->type_name("A:B");
    command->add_flag("-q,--quiet", options->quiet, "No summary line on stderr");
    return {command, [options] { return run_export(*options); }};
}

}  // namespace collidescope::app
