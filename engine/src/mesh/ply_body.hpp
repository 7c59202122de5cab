#pragma once
// Readers of the PLY body, ascii and binary (engine/src/mesh, private).
//
// parse_ply resolves the header into a Layout once (which element holds the positions, which
// property the face corners), so the body loops touch no strings.

#include "collidescope/mesh.hpp"
#include "mesh/ply_header.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace collidescope::ply {

/// Where the mesh lives in the body; -1 where absent.
struct Layout {
    int vertex_element = -1;  ///< index into Header::elements
    int face_element = -1;
    int x = -1, y = -1, z = -1;  ///< property indices within the vertex element
    int corners = -1;            ///< the vertex_indices list within the face element
};

/// Resolves the vertex and face elements and their properties; throws InputError naming
/// `source` when x/y/z or the corner list are missing or of the wrong kind.
Layout resolve_layout(const Header& header, std::string_view source);

/// Reads the binary body (the bytes after end_header) into `mesh`.
void read_binary_body(std::span<const std::byte> body, const Header& header, const Layout& layout,
                      MeshData& mesh, std::string_view source);

/// Reads the ascii body into `mesh`.
void read_ascii_body(std::string_view body, const Header& header, const Layout& layout,
                     MeshData& mesh, std::string_view source);

/// Throws "SOURCE: ELEMENT INDEX: WHAT", e.g. "cloth.0003.ply: vertex 17: file truncated".
[[noreturn]] void throw_item_error(std::string_view source, std::string_view element,
                                   std::uint64_t item, const std::string& what);

/// The upper bound for corner indices while reading faces: the vertex count when the vertex
/// element came first, otherwise 2^32 - 1 (validate_mesh then checks the range).
struct CornerLimit {
    std::uint64_t limit = 0xffffffffu;
    bool vertices_known = false;
};

/// Checks one corner index read from face `face`; returns it as uint32.
inline std::uint32_t checked_corner(std::int64_t index, const CornerLimit& limit,
                                    std::string_view source, std::uint64_t face) {
    if (static_cast<std::uint64_t>(index) < limit.limit) return static_cast<std::uint32_t>(index);
    std::string what = "vertex index " + std::to_string(index) + " out of range";
    if (limit.vertices_known) what += " (" + std::to_string(limit.limit) + " vertices)";
    throw_item_error(source, "face", face, what);
}

}  // namespace collidescope::ply
