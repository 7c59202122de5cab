// The mesh readers' fuzz entries: the bytes of a .ply or .obj file, read as read_mesh_file
// reads them (parse, then validate_mesh), without the file system in between.

#include "entries.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

namespace collidescope::fuzz {

Outcome read_ply(std::span<const std::byte> bytes) {
    try {
        const MeshData mesh = parse_ply(bytes, "fuzz.ply");
        validate_mesh(mesh, "fuzz.ply");
        return Outcome::Accepted;
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
}

Outcome read_obj(std::span<const std::byte> bytes) {
    try {
        const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        const MeshData mesh = parse_obj(text, "fuzz.obj");
        validate_mesh(mesh, "fuzz.obj");
        return Outcome::Accepted;
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
}

Entry entry_named(std::string_view target) {
    if (target == "ply") return read_ply;
    if (target == "obj") return read_obj;
    if (target == "scene") return read_scene;
    if (target == "trace") return read_trace;
    return nullptr;
}

}  // namespace collidescope::fuzz
