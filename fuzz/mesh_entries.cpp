// The mesh readers' fuzz entries: the bytes of a .ply or .obj file, read as read_mesh_file
// reads them (parse, then validate_mesh), without the file system in between; and the bytes
// of a point cache, through a file (the reader seeks in it).

#include "entries.hpp"
#include "scratch.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/point_cache.hpp"

#include <algorithm>
#include <cstring>

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

Outcome read_cache(std::span<const std::byte> bytes) {
    const bool pc2 = bytes.size() >= 11 && std::memcmp(bytes.data(), "POINTCACHE2", 11) == 0;
    const std::filesystem::path file = scratch_dir() / (pc2 ? "fuzz.pc2" : "fuzz.mdd");
    write_file(file, bytes);
    try {
        PointCacheReader reader(file);
        // The header check makes the frames fill the file, so a fuzz input holds few of them;
        // the bound only guards a harness bug.
        const std::uint32_t frames = std::min<std::uint32_t>(reader.layout().frame_count, 4096);
        for (std::uint32_t k = 0; k < frames; ++k) (void)reader.read_frame(k);
        return Outcome::Accepted;
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
}

Entry entry_named(std::string_view target) {
    if (target == "ply") return read_ply;
    if (target == "obj") return read_obj;
    if (target == "scene") return read_scene;
    if (target == "recording") return read_recording;
    if (target == "cache") return read_cache;
    return nullptr;
}

}  // namespace collidescope::fuzz
