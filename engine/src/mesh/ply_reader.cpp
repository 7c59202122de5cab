// parse_ply: the project's own PLY reader (header, layout, then the ascii or binary body).
//
// Our own reader rather than assimp's: it is faster on large binary caches, reports
// truncation with the element and item, and keeps the file's vertices and faces exactly.

#include "mesh/ply_body.hpp"
#include "mesh/ply_header.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <limits>

namespace collidescope {
namespace ply {
namespace {

[[noreturn]] void fail(std::string_view source, const std::string& what) {
    throw InputError(std::string(source) + ": " + what);
}

int find_element(const Header& header, std::string_view name) {
    for (std::size_t e = 0; e < header.elements.size(); ++e) {
        if (header.elements[e].name == name) return static_cast<int>(e);
    }
    return -1;
}

int find_scalar(const Element& element, std::string_view name, std::string_view source) {
    const int index = element.find(name);
    if (index < 0) fail(source, "vertex element has no property '" + std::string(name) + "'");
    if (element.properties[index].is_list) {
        fail(source, "vertex property '" + std::string(name) + "' is a list");
    }
    return index;
}

int find_corner_list(const Element& element, std::string_view source) {
    int index = element.find("vertex_indices");
    if (index < 0) index = element.find("vertex_index");
    if (index < 0) fail(source, "face element has no vertex_indices property");
    const Property& property = element.properties[index];
    if (!property.is_list) fail(source, "face property '" + property.name + "' is not a list");
    if (is_floating(property.type)) {
        fail(source, "face property '" + property.name + "' holds floating-point indices");
    }
    return index;
}

}  // namespace

Layout resolve_layout(const Header& header, std::string_view source) {
    Layout layout;
    layout.vertex_element = find_element(header, "vertex");
    if (layout.vertex_element < 0) fail(source, "no vertex element");
    const Element& vertices = header.elements[layout.vertex_element];
    if (vertices.count > std::numeric_limits<std::uint32_t>::max()) {
        fail(source, "too many vertices (" + std::to_string(vertices.count) + ")");
    }
    layout.x = find_scalar(vertices, "x", source);
    layout.y = find_scalar(vertices, "y", source);
    layout.z = find_scalar(vertices, "z", source);
    layout.face_element = find_element(header, "face");
    if (layout.face_element >= 0) {
        layout.corners = find_corner_list(header.elements[layout.face_element], source);
    }
    return layout;
}

void throw_item_error(std::string_view source, std::string_view element, std::uint64_t item,
                      const std::string& what) {
    throw InputError(std::string(source) + ": " + std::string(element) + " " +
                     std::to_string(item) + ": " + what);
}

}  // namespace ply

MeshData parse_ply(std::span<const std::byte> bytes, std::string_view source) {
    const ply::Header header = ply::parse_header(bytes, source);
    const ply::Layout layout = ply::resolve_layout(header, source);
    const std::span<const std::byte> body = bytes.subspan(header.body_offset);
    MeshData mesh;
    if (header.format == ply::Format::Ascii) {
        const std::string_view text(reinterpret_cast<const char*>(body.data()), body.size());
        ply::read_ascii_body(text, header, layout, mesh, source);
    } else {
        ply::read_binary_body(body, header, layout, mesh, source);
    }
    if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
        ply::fail(source, "too many triangles (" + std::to_string(mesh.triangles.size()) + ")");
    }
    return mesh;
}

}  // namespace collidescope
