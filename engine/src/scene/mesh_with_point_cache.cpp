// Mesh + point cache objects: `body.obj@body.pc2` on the command line, {"mesh", "cache"} in a
// scene.json (docs/how-to/point-caches.md).

#include "scene/mesh_with_point_cache.hpp"
#include "scene/frame_pattern.hpp"

#include "collidescope/error.hpp"

namespace collidescope {

std::optional<CacheSpec> parse_cache_spec(const std::string& spec) {
    std::error_code error;
    if (std::filesystem::exists(spec, error)) return std::nullopt;
    const std::size_t at = spec.rfind('@');
    if (at == std::string::npos || at == 0) return std::nullopt;
    CacheSpec parts{spec.substr(0, at), spec.substr(at + 1)};
    if (!is_point_cache_file(parts.cache)) return std::nullopt;
    return parts;
}

FileObject open_mesh_with_point_cache(const std::string& mesh, const std::string& cache, const std::string& name) {
    const std::filesystem::path mesh_path(mesh);
    std::error_code error;
    if (!std::filesystem::is_regular_file(mesh_path, error)) {
        if (std::filesystem::exists(mesh_path, error)) throw InputError(mesh + ": not a regular file");
        if (parse_frame_pattern(mesh)) {
            throw InputError(mesh + ": a point cache needs one mesh file, not a frame pattern (cache " + cache + ")");
        }
        throw InputError(mesh + ": no such file (the mesh of point cache " + cache + ")");
    }
    FileObject object;
    object.origin = mesh + "@" + cache;
    object.files = {mesh_path};
    object.cache = std::make_shared<PointCacheReader>(cache);
    object.cache_frames = object.cache->layout().frame_count;
    object.name = name.empty() ? object_name_from(mesh_path.filename().string()) : name;
    return object;
}

}  // namespace collidescope
