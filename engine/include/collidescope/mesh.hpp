#pragma once
/// Meshes as read from files, and the readers (engine/src/mesh).
///
/// Readers keep the file's vertex order, face order and vertex sharing: pair indices refer to
/// file order, and the self-collision rule depends on the file's own vertex indices. Polygons
/// with more than three corners are split as fans (v0, vi, vi+1), triangle ids counting the
/// resulting triangles in file order. Every reader throws InputError naming the file and the
/// element (line, byte offset, vertex or face index) on malformed input; none ever aborts.

#include "collidescope/types.hpp"

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

/// One mesh as read from one file: positions and triangles, both in file order.
struct MeshData {
    std::vector<Vec3> vertices;
    std::vector<TriIndices> triangles;
};

/// Reads a mesh file, choosing the reader by extension: .ply and .obj (optionally .gz) use
/// the project's own readers, anything else goes through assimp. Validates the result
/// (validate_mesh) before returning it.
MeshData read_mesh_file(const std::filesystem::path& file);

/// Parses PLY bytes (ascii, binary_little_endian, binary_big_endian; float or double
/// coordinates; extra vertex properties and elements ignored). `source` names the file in
/// error messages.
MeshData parse_ply(std::span<const std::byte> bytes, std::string_view source);

/// Parses OBJ text (v and f records; f accepts v, v/vt, v//vn, v/vt/vn and negative indices;
/// everything else ignored). `source` names the file in error messages.
MeshData parse_obj(std::string_view text, std::string_view source);

/// Reads any format assimp reads, without post-processing that reorders or merges vertices.
MeshData read_with_assimp(const std::filesystem::path& file);

/// Checks a mesh at the input boundary: at least one triangle, every index < vertex count,
/// every coordinate finite. Throws InputError naming `source` and the first bad element.
void validate_mesh(const MeshData& mesh, std::string_view source);

/// Writes a mesh as binary little-endian PLY with float32 coordinates (double when
/// `double_precision`), vertices and faces in the given order.
void write_ply(const std::filesystem::path& file, const MeshData& mesh,
               bool double_precision = false);

/// Reads a whole file into memory, transparently gunzipping when it ends in .gz.
/// Throws InputError when the file is missing or unreadable.
std::vector<std::byte> read_file_bytes(const std::filesystem::path& file);

}  // namespace collidescope
