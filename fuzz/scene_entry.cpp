// The scene fuzz entry: the input is a scene.json manifest in a directory that holds a few
// small frame files, so its patterns (printf fields, runs of #, static files, "frames",
// relative paths) expand to real sequences; open_inputs then reads every frame, as `check`
// and `record` do.

#include "entries.hpp"
#include "scratch.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/scene.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope::fuzz {
namespace {

// A tetrahedron moved along x by `shift`.
MeshData tetrahedron(double shift) {
    MeshData mesh;
    mesh.vertices = {Vec3(shift, 0, 0), Vec3(shift + 1, 0, 0), Vec3(shift, 1, 0), Vec3(shift, 0, 1)};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

std::string obj_text(const MeshData& mesh) {
    std::string text;
    for (const Vec3& v : mesh.vertices) {
        text += "v " + std::to_string(v.x()) + ' ' + std::to_string(v.y()) + ' ' + std::to_string(v.z()) + '\n';
    }
    for (const TriIndices& t : mesh.triangles) {
        text += "f " + std::to_string(t[0] + 1) + ' ' + std::to_string(t[1] + 1) + ' ' + std::to_string(t[2] + 1) + '\n';
    }
    return text;
}

// tet.pc2: three frames of a tetrahedron's 4 points (floor.ply's count), for {"mesh", "cache"}.
std::vector<std::byte> tetrahedron_pc2() {
    std::vector<std::byte> bytes;
    const auto put = [&](std::uint32_t bits) {  // little-endian
        for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<std::byte>(bits >> (8 * b)));
    };
    for (const char c : std::string_view("POINTCACHE2\0", 12)) bytes.push_back(static_cast<std::byte>(c));
    constexpr std::uint32_t k_samples = 3;
    put(1);                               // version
    put(4);                               // points
    put(std::bit_cast<std::uint32_t>(0.0f));  // start frame
    put(std::bit_cast<std::uint32_t>(1.0f));  // sample rate
    put(k_samples);
    for (std::uint32_t f = 0; f < k_samples; ++f) {
        for (const Vec3& v : tetrahedron(-3 + 0.2 * f).vertices) {
            for (int axis = 0; axis < 3; ++axis) put(std::bit_cast<std::uint32_t>(static_cast<float>(v[axis])));
        }
    }
    return bytes;
}

// cloth.0000.ply .. cloth.0002.ply, body.0000.obj .. body.0002.obj, floor.ply (static),
// sub/cap.1.obj, sub/cap.2.obj and tet.pc2: what the seed manifests name. A gap in a pattern's numbers is
// an error (tests/app/test_error_table.cpp), so the valid seeds hold none.
const std::filesystem::path& scene_dir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path made = scratch_dir() / "scene";
        std::filesystem::create_directories(made / "sub");
        for (int f = 0; f < 3; ++f) {
            const std::string number = "000" + std::to_string(f);
            write_ply(made / ("cloth." + number + ".ply"), tetrahedron(0.1 * f));
            const std::string obj = obj_text(tetrahedron(0.5 - 0.1 * f));
            write_file(made / ("body." + number + ".obj"), std::as_bytes(std::span(obj)));
        }
        write_ply(made / "floor.ply", tetrahedron(-3), true);
        write_file(made / "tet.pc2", tetrahedron_pc2());
        for (int f = 1; f <= 2; ++f) {
            const std::string cap = obj_text(tetrahedron(f));
            write_file(made / "sub" / ("cap." + std::to_string(f) + ".obj"), std::as_bytes(std::span(cap)));
        }
        return made;
    }();
    return dir;
}

}  // namespace

Outcome read_scene(std::span<const std::byte> bytes) {
    const std::filesystem::path manifest = scene_dir() / "scene.json";
    write_file(manifest, bytes);
    try {
        const std::string input = manifest.string();
        const Scene scene = open_inputs(std::span(&input, 1));
        FrameSource& source = *scene.source;
        for (std::uint32_t k = 0; k < source.object_count(); ++k) (void)source.object_name(k);
        // The directory holds at most a handful of frames; the bound only guards a harness bug.
        const std::uint32_t frames = std::min<std::uint32_t>(source.frame_count(), 16);
        for (std::uint32_t f = 0; f < frames; ++f) (void)source.frame(f);
        return Outcome::Accepted;
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
}

}  // namespace collidescope::fuzz
