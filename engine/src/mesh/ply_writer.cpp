// write_ply: binary little-endian PLY, vertices then faces, in the mesh's order.

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <bit>
#include <cstdio>
#include <cstring>
#include <memory>

namespace collidescope {
namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

template <class T>
void append_le(std::vector<std::byte>& out, T value) {
    static_assert(std::endian::native == std::endian::little, "write_ply assumes a little-endian host");
    const std::size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

std::string header_text(const MeshData& mesh, bool double_precision) {
    const char* type = double_precision ? "double" : "float";
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by collidescope\n";
    header += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
    for (const char* axis : {"x", "y", "z"}) header += std::string("property ") + type + " " + axis + "\n";
    header += "element face " + std::to_string(mesh.triangles.size()) + "\n";
    header += "property list uchar int vertex_indices\nend_header\n";
    return header;
}

}  // namespace

void write_ply(const std::filesystem::path& file, const MeshData& mesh, bool double_precision) {
    const std::string header = header_text(mesh, double_precision);
    std::vector<std::byte> bytes;
    const std::size_t scalar = double_precision ? 8 : 4;
    bytes.reserve(header.size() + mesh.vertices.size() * 3 * scalar + mesh.triangles.size() * 13);
    for (const char c : header) bytes.push_back(static_cast<std::byte>(c));
    for (const Vec3& vertex : mesh.vertices) {
        for (int axis = 0; axis < 3; ++axis) {
            // float32 output rounds each coordinate to nearest; double keeps it exactly.
            if (double_precision) {
                append_le(bytes, vertex[axis]);
            } else {
                append_le(bytes, static_cast<float>(vertex[axis]));
            }
        }
    }
    for (const TriIndices& triangle : mesh.triangles) {
        append_le(bytes, std::uint8_t{3});
        for (const std::uint32_t corner : triangle) append_le(bytes, static_cast<std::int32_t>(corner));
    }
    const std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(file.c_str(), "wb"));
    const bool written = stream && std::fwrite(bytes.data(), 1, bytes.size(), stream.get()) == bytes.size();
    if (!written || std::fflush(stream.get()) != 0) {
        throw InputError(file.string() + ": cannot write PLY file");
    }
}

}  // namespace collidescope
