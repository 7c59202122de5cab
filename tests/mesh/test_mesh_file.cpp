// read_mesh_file: the reader by extension (PLY, OBJ, .gz, assimp for the rest), file errors
// (missing, corrupt or truncated gzip), and validate_mesh's checks.

#include "mesh/temp_files.hpp"

#include "collidescope/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <limits>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

MeshData square_pyramid() {
    MeshData mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    return mesh;
}

std::vector<std::byte> file_bytes(const std::filesystem::path& file) { return read_file_bytes(file); }

void gzip_file(const std::filesystem::path& from, const std::filesystem::path& to) {
    const std::vector<std::byte> bytes = file_bytes(from);
    gzFile out = gzopen(to.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    ASSERT_EQ(gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size())), static_cast<int>(bytes.size()));
    ASSERT_EQ(gzclose(out), Z_OK);
}

TEST(MeshFile, PlyAndObjByExtensionInAnyCase) {
    TempDir dir;
    const MeshData mesh = square_pyramid();
    write_ply(dir / "p.PLY", mesh);
    write_text(dir / "p.Obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                              "f 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
    const MeshData ply = read_mesh_file(dir / "p.PLY");
    const MeshData obj = read_mesh_file(dir / "p.Obj");
    EXPECT_EQ(ply.vertices, mesh.vertices);
    EXPECT_EQ(ply.triangles, mesh.triangles);
    EXPECT_EQ(obj.vertices, mesh.vertices);
    EXPECT_EQ(obj.triangles, mesh.triangles);
}

TEST(MeshFile, GzipRoundTrip) {
    TempDir dir;
    const MeshData mesh = square_pyramid();
    write_ply(dir / "p.ply", mesh, true);
    gzip_file(dir / "p.ply", dir / "p.ply.gz");
    write_text(dir / "p.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 3 4\n");
    gzip_file(dir / "p.obj", dir / "p.obj.gz");
    EXPECT_EQ(file_bytes(dir / "p.ply.gz"), file_bytes(dir / "p.ply"));
    const MeshData ply = read_mesh_file(dir / "p.ply.gz");
    EXPECT_EQ(ply.vertices, mesh.vertices);
    EXPECT_EQ(ply.triangles, mesh.triangles);
    const MeshData obj = read_mesh_file(dir / "p.obj.gz");
    EXPECT_EQ(obj.triangles, (std::vector<TriIndices>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(MeshFile, BadFilesNameThePath) {
    TempDir dir;
    const std::string missing = (dir / "missing.ply").string();
    EXPECT_EQ(input_error([&] { read_mesh_file(missing); }), missing + ": no such file");
    std::filesystem::create_directory(dir / "folder.ply");
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "folder.ply"); }),
              (dir / "folder.ply").string() + ": is a directory, not a file");
    EXPECT_THAT(input_error([&] { read_mesh_file(dir.path()); }), HasSubstr("is a directory"));
    write_ply(dir / "p.ply", square_pyramid());
    gzip_file(dir / "p.ply", dir / "p.ply.gz");
    std::vector<std::byte> gz = file_bytes(dir / "p.ply");
    write_bytes(dir / "plain.ply.gz", gz);
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "plain.ply.gz"); }),
              (dir / "plain.ply.gz").string() + ": not gzip data");
    std::ifstream in(dir / "p.ply.gz", std::ios::binary);
    std::vector<char> compressed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    compressed.resize(compressed.size() / 2);
    write_text(dir / "cut.ply.gz", std::string_view(compressed.data(), compressed.size()));
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "cut.ply.gz"); }),
              (dir / "cut.ply.gz").string() + ": gzip data truncated");
    compressed[12] = static_cast<char>(compressed[12] ^ 0x55);
    compressed[13] = static_cast<char>(compressed[13] ^ 0x55);
    write_text(dir / "corrupt.ply.gz", std::string_view(compressed.data(), compressed.size()));
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "corrupt.ply.gz"); }),
                HasSubstr("corrupt.ply.gz: "));
}

TEST(MeshFile, TruncatedPlyFileNamesFileAndVertex) {
    TempDir dir;
    write_ply(dir / "cloth.0003.ply", square_pyramid());
    std::vector<std::byte> bytes = file_bytes(dir / "cloth.0003.ply");
    const std::size_t header = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())
                                   .find("end_header\n") + 11;
    bytes.resize(header + 12 * 3 + 5);
    write_bytes(dir / "cloth.0003.ply", bytes);
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "cloth.0003.ply"); }),
              (dir / "cloth.0003.ply").string() + ": vertex 3: file truncated: expected 12 bytes at byte " +
                  std::to_string(header + 36) + ", the file ends at byte " + std::to_string(header + 41));
}

// OFF goes through assimp, whose OFF importer keeps the file's vertices and faces.
TEST(MeshFile, AssimpFormatKeepsOrderAndSplitsFans) {
    TempDir dir;
    write_text(dir / "a.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                              "4 0 1 2 3\n3 0 1 4\n3 2 3 4\n");
    const MeshData mesh = read_mesh_file(dir / "a.off");
    EXPECT_EQ(mesh.vertices, square_pyramid().vertices);
    const std::vector<TriIndices> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {2, 3, 4}};
    EXPECT_EQ(mesh.triangles, expected);
    gzip_file(dir / "a.off", dir / "a.off.gz");
    EXPECT_EQ(read_mesh_file(dir / "a.off.gz").triangles, expected);
}

// glTF through assimp: the node tree's transforms (a parent translation and a child one)
// are applied, vertex and index order kept.
TEST(MeshFile, AssimpAppliesNodeTransforms) {
    TempDir dir;
    ByteWriter buffer;
    const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5f}};
    for (const auto& p : positions) {
        for (const float c : p) buffer.put(c);
    }
    for (const int i : {0, 1, 2, 0, 2, 3}) buffer.put(static_cast<std::uint16_t>(i));
    write_bytes(dir / "quad.bin", buffer.bytes());
    write_text(dir / "quad.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"translation": [10, 0, 0], "children": [1]}, {"mesh": 0, "translation": [0, 0, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"uri": "quad.bin", "byteLength": 60}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0.5]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})");
    const MeshData mesh = read_mesh_file(dir / "quad.gltf");
    ASSERT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.vertices[0], Vec3(10, 0, 1));
    EXPECT_EQ(mesh.vertices[3], Vec3(10, 1, 1.5));
    EXPECT_EQ(mesh.triangles, (std::vector<TriIndices>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(MeshFile, AssimpErrorsNameTheFile) {
    TempDir dir;
    write_text(dir / "junk.off", "this is not an OFF file\n");
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "junk.off"); }), HasSubstr("junk.off: "));
    EXPECT_THAT(input_error([&] { read_with_assimp(dir / "none.stl"); }), HasSubstr("none.stl: no such file"));
}

TEST(ValidateMesh, NamesSourceAndElement) {
    MeshData mesh = square_pyramid();
    EXPECT_NO_THROW(validate_mesh(mesh, "ok.ply"));
    MeshData empty = mesh;
    empty.triangles.clear();
    EXPECT_EQ(input_error([&] { validate_mesh(empty, "e.ply"); }), "e.ply: no triangles (empty mesh)");
    MeshData out_of_range = mesh;
    out_of_range.triangles[4][1] = 9000;
    EXPECT_EQ(input_error([&] { validate_mesh(out_of_range, "bunny.obj"); }),
              "bunny.obj: triangle 4: vertex index 9000 out of range (5 vertices)");
    MeshData nan = mesh;
    nan.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(input_error([&] { validate_mesh(nan, "n.ply"); }),
              "n.ply: vertex 3: coordinate x is not finite (nan)");
    MeshData inf = mesh;
    inf.vertices[2].z() = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(input_error([&] { validate_mesh(inf, "i.ply"); }),
              "i.ply: vertex 2: coordinate z is not finite (-inf)");
}

TEST(ValidateMesh, FilesWithoutFacesOrWithNonFiniteValues) {
    TempDir dir;
    write_text(dir / "points.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                   "property float y\nproperty float z\nend_header\n0 0 0\n");
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "points.ply"); }),
              (dir / "points.ply").string() + ": no triangles (empty mesh)");
    write_text(dir / "nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n");
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "nan.ply"); }),
              (dir / "nan.ply").string() + ": vertex 2: coordinate y is not finite (inf)");
    write_text(dir / "empty.obj", "# nothing\n");
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "empty.obj"); }), HasSubstr("empty.obj: no triangles"));
}

}  // namespace
}  // namespace collidescope
