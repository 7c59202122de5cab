// read_mesh_file (reader by extension, then validation) and validate_mesh.

#include "mesh/format_extension.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace collidescope {
namespace {

[[noreturn]] void fail(std::string_view source, const std::string& what) {
    throw InputError(std::string(source) + ": " + what);
}

}  // namespace

MeshData read_mesh_file(const std::filesystem::path& file) {
    const std::string source = file.string();
    const std::string extension = format_extension(file);
    MeshData mesh;
    if (extension == ".ply") {
        const std::vector<std::byte> bytes = read_file_bytes(file);
        mesh = parse_ply(bytes, source);
    } else if (extension == ".obj") {
        const std::vector<std::byte> bytes = read_file_bytes(file);
        mesh = parse_obj({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, source);
    } else {
        mesh = read_with_assimp(file);
    }
    validate_mesh(mesh, source);
    return mesh;
}

void validate_mesh(const MeshData& mesh, std::string_view source) {
    if (mesh.triangles.empty()) fail(source, "no triangles (empty mesh)");
    const std::size_t vertex_count = mesh.vertices.size();
    if (vertex_count > std::numeric_limits<std::uint32_t>::max()) {
        fail(source, "too many vertices (" + std::to_string(vertex_count) + ")");
    }
    for (std::size_t v = 0; v < vertex_count; ++v) {
        const Vec3& vertex = mesh.vertices[v];
        for (int axis = 0; axis < 3; ++axis) {
            if (std::isfinite(vertex[axis])) continue;
            fail(source, "vertex " + std::to_string(v) + ": coordinate " + "xyz"[axis] +
                             " is not finite (" + std::to_string(vertex[axis]) + ")");
        }
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (const std::uint32_t corner : mesh.triangles[t]) {
            if (corner < vertex_count) continue;
            fail(source, "triangle " + std::to_string(t) + ": vertex index " +
                             std::to_string(corner) + " out of range (" +
                             std::to_string(vertex_count) + " vertices)");
        }
    }
}

}  // namespace collidescope
