#pragma once
// Mesh + point cache objects (engine/src/scene, private): the command line's `MESH@CACHE`
// form and the object open_inputs makes of a mesh and its cache.

#include "scene/file_source.hpp"

#include <optional>
#include <string>

namespace collidescope {

/// A mesh and its point cache, as given.
struct CacheSpec {
    std::string mesh;
    std::string cache;
};

/// Splits `MESH@CACHE` at its last '@' when the part after it names a point cache (.pc2 or
/// .mdd) and `spec` itself is not an existing file; nothing otherwise.
std::optional<CacheSpec> parse_cache_spec(const std::string& spec);

/// An object whose triangles come from `mesh` (one mesh file, not a pattern) and whose frames
/// are the frames of `cache`, named `name` or after the mesh. Opens the cache and checks its
/// header; the mesh is read (and its vertex count compared with the cache's) with frame 0.
/// Throws InputError naming the file on a missing mesh or a bad cache header.
FileObject open_mesh_with_point_cache(const std::string& mesh, const std::string& cache, const std::string& name);

}  // namespace collidescope
