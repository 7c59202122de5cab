// parse_ply and write_ply: round trips, hand-written ascii / little / big-endian files with
// extra properties and elements, fan order, and every malformed or truncated body.

#include "mesh/temp_files.hpp"

#include "collidescope/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

MeshData sample_mesh() {
    MeshData mesh;
    mesh.vertices = {{0.1, -2.5, 3.0}, {1e-30, 1e30, -0.0}, {3.14159265358979, 2.0 / 3.0, 7.0},
                     {-1.0, 0.25, 1e-300}};
    mesh.triangles = {{0, 1, 2}, {2, 1, 3}, {3, 0, 1}};
    return mesh;
}

TEST(PlyRoundTrip, FloatRoundsEachCoordinateOnce) {
    TempDir dir;
    const MeshData mesh = sample_mesh();
    write_ply(dir / "m.ply", mesh);
    const MeshData read = parse_ply(read_file_bytes(dir / "m.ply"), "m.ply");
    ASSERT_EQ(read.vertices.size(), mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_EQ(read.vertices[v][axis], round_to_float32(mesh.vertices[v][axis]));
        }
    }
    EXPECT_EQ(read.triangles, mesh.triangles);
}

TEST(PlyRoundTrip, DoubleIsExact) {
    TempDir dir;
    const MeshData mesh = sample_mesh();
    write_ply(dir / "m.ply", mesh, true);
    const MeshData read = parse_ply(read_file_bytes(dir / "m.ply"), "m.ply");
    EXPECT_EQ(read.vertices, mesh.vertices);
    EXPECT_EQ(read.triangles, mesh.triangles);
}

// Vertices with normals and colours, an "edge" element with a list before the faces, faces
// with an extra list and an extra scalar, a quad and a pentagon.
constexpr std::string_view k_ascii_ply =
    "ply\r\nformat ascii 1.0\ncomment hand written\nobj_info test\n"
    "element vertex 5\nproperty float x\nproperty float nx\nproperty double y\n"
    "property float z\nproperty uchar red\n"
    "element edge 2\nproperty list uchar int ends\nproperty float weight\n"
    "element face 3\nproperty list uchar float texcoord\nproperty list uchar int vertex_indices\n"
    "property int flags\nend_header\n"
    "0.1 9 0.1 0 255\n1 9 0 0 1\n1 9 1 0 2\n0 9 1 0 3\n+0.5 9 0.5 -1e2 4\n"
    "2 0 1 0.5\n3 1 2 3 7.5\n"
    "0 4 0 1 2 3 11\n6 0 0 1 1 0 1 3 0 1 4 12\n2 0.5 0.5 5 4 3 2 1 0 13\n";

TEST(PlyAscii, SkipsExtraPropertiesAndElementsAndSplitsFans) {
    const MeshData mesh = parse_ply(as_bytes(k_ascii_ply), "hand.ply");
    ASSERT_EQ(mesh.vertices.size(), 5u);
    // x and z are declared float: parsed as float32, as a binary file would hold them.
    EXPECT_EQ(mesh.vertices[0], Vec3(static_cast<double>(0.1f), 0.1, 0.0));
    EXPECT_EQ(mesh.vertices[4], Vec3(0.5, 0.5, -100.0));
    const std::vector<TriIndices> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4},
                                              {4, 3, 2}, {4, 2, 1}, {4, 1, 0}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(PlyAscii, TruncatedNamesElementAndItem) {
    const std::string text(k_ascii_ply.substr(0, k_ascii_ply.find("1 9 1 0 2")));
    const std::string message = input_error([&] { parse_ply(as_bytes(text), "cloth.0003.ply"); });
    EXPECT_EQ(message, "cloth.0003.ply: vertex 2: file truncated: expected 5 vertex items, the file ends inside this one "
                       "(line 21)");
    const std::string in_faces(k_ascii_ply.substr(0, k_ascii_ply.size() - 6));
    EXPECT_EQ(input_error([&] { parse_ply(as_bytes(in_faces), "a.ply"); }),
              "a.ply: face 2: file truncated: expected 3 face items, the file ends inside this one (line 28)");
}

TEST(PlyAscii, BadNumberNamesItemAndLine) {
    std::string text(k_ascii_ply);
    text[text.find("1 9 1 0 2")] = 'x';
    const std::string message = input_error([&] { parse_ply(as_bytes(text), "a.ply"); });
    EXPECT_THAT(message, HasSubstr("a.ply: vertex 2: bad number 'x'"));
    EXPECT_THAT(message, HasSubstr("line 21"));
}

// The same layout as k_ascii_ply, in binary, byte order chosen by the writer.
ByteWriter binary_ply(bool big_endian) {
    ByteWriter w(big_endian);
    w.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\nelement vertex 4\nproperty float x\nproperty float nx\nproperty double y\n"
           "property float z\nproperty uchar red\n"
           "element edge 1\nproperty list uchar int ends\nproperty float weight\n"
           "element face 2\nproperty list int ushort vertex_index\nproperty uchar flags\n"
           "end_header\n");
    const float xs[4] = {0.1f, 1, 1, 0};
    const double ys[4] = {0.1, 0, 1, 1};
    for (int v = 0; v < 4; ++v) {
        w.put(xs[v]);
        w.put(9.0f);
        w.put(ys[v]);
        w.put(-0.5f);
        w.put(std::uint8_t{200});
    }
    w.put(std::uint8_t{2});
    w.put(std::int32_t{0});
    w.put(std::int32_t{1});
    w.put(0.5f);
    w.put(std::int32_t{4});
    for (const int i : {3, 2, 1, 0}) w.put(static_cast<std::uint16_t>(i));
    w.put(std::uint8_t{1});
    w.put(std::int32_t{3});
    for (const int i : {0, 1, 3}) w.put(static_cast<std::uint16_t>(i));
    w.put(std::uint8_t{2});
    return w;
}

void expect_binary_mesh(const MeshData& mesh) {
    ASSERT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.vertices[0], Vec3(static_cast<double>(0.1f), 0.1, -0.5));
    EXPECT_EQ(mesh.vertices[2], Vec3(1.0, 1.0, -0.5));
    const std::vector<TriIndices> expected = {{3, 2, 1}, {3, 1, 0}, {0, 1, 3}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(PlyBinary, LittleEndianGeneralLayout) {
    expect_binary_mesh(parse_ply(binary_ply(false).span(), "le.ply"));
}

TEST(PlyBinary, BigEndianGeneralLayout) {
    expect_binary_mesh(parse_ply(binary_ply(true).span(), "be.ply"));
}

// The common layout (xyz of one type, faces "uchar + int"), which takes the fast loops.
ByteWriter common_ply(bool big_endian, bool doubles) {
    ByteWriter w(big_endian);
    const std::string type = doubles ? "double" : "float";
    w.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\nelement vertex 5\nproperty " + type + " x\nproperty " + type + " y\nproperty " +
           type + " z\nproperty float confidence\nelement face 3\n"
           "property list uchar uint vertex_indices\nend_header\n");
    for (int v = 0; v < 5; ++v) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = 0.1 * v + axis;
            doubles ? w.put(value) : w.put(static_cast<float>(value));
        }
        w.put(1.0f);
    }
    const std::vector<std::vector<std::uint32_t>> faces = {{0, 1, 2}, {1, 2, 3, 4}, {4, 0, 2}};
    for (const auto& face : faces) {
        w.put(static_cast<std::uint8_t>(face.size()));
        for (const std::uint32_t i : face) w.put(i);
    }
    return w;
}

TEST(PlyBinary, CommonLayoutsInBothByteOrdersAndPrecisions) {
    for (const bool big_endian : {false, true}) {
        for (const bool doubles : {false, true}) {
            SCOPED_TRACE(::testing::Message() << "big_endian " << big_endian << " doubles " << doubles);
            const MeshData mesh = parse_ply(common_ply(big_endian, doubles).span(), "c.ply");
            ASSERT_EQ(mesh.vertices.size(), 5u);
            const double y3 = 0.1 * 3 + 1;
            EXPECT_EQ(mesh.vertices[3].y(), doubles ? y3 : round_to_float32(y3));
            const std::vector<TriIndices> expected = {{0, 1, 2}, {1, 2, 3}, {1, 3, 4}, {4, 0, 2}};
            EXPECT_EQ(mesh.triangles, expected);
        }
    }
}

TEST(PlyBinary, TruncatedVertexAndFaceNamed) {
    const ByteWriter writer = common_ply(false, false);
    const std::vector<std::byte>& bytes = writer.bytes();
    const std::size_t header = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())
                                   .find("end_header\n") + 11;
    // Vertex records are 16 bytes: cut inside vertex 2.
    const auto cut = [&](std::size_t size) { return std::span<const std::byte>(bytes.data(), size); };
    EXPECT_EQ(input_error([&] { parse_ply(cut(header + 40), "cloth.0003.ply"); }),
              "cloth.0003.ply: vertex 2: file truncated: expected 16 bytes at byte " + std::to_string(header + 32) +
                  ", the file ends at byte " + std::to_string(header + 40));
    // Faces start after 5 * 16 bytes; face 0 takes 13 bytes, cut inside face 1's list.
    // Its count byte is there; its four indices (16 bytes) are not.
    EXPECT_EQ(input_error([&] { parse_ply(cut(header + 80 + 13 + 5), "cloth.0003.ply"); }),
              "cloth.0003.ply: face 1: file truncated: expected 16 bytes at byte " + std::to_string(header + 94) +
                  ", the file ends at byte " + std::to_string(header + 98));
    const ByteWriter general_writer = binary_ply(false);
    const std::vector<std::byte>& general = general_writer.bytes();
    EXPECT_EQ(input_error([&] { parse_ply(std::span(general.data(), general.size() - 3), "g.ply"); }),
              "g.ply: face 1: file truncated: expected 6 bytes at byte 407, the file ends at byte 411");
}

TEST(PlyBinary, FacesBeforeVerticesAndIntegerCoordinates) {
    ByteWriter w;
    w.text("ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
           "element vertex 3\nproperty short x\nproperty int y\nproperty uchar z\nend_header\n");
    w.put(std::uint8_t{3});
    for (std::int32_t i : {2, 0, 1}) w.put(i);
    for (int v = 0; v < 3; ++v) {
        w.put(static_cast<std::int16_t>(-v));
        w.put(std::int32_t{1000000 * v});
        w.put(static_cast<std::uint8_t>(250 + v));
    }
    const MeshData mesh = parse_ply(w.span(), "i.ply");
    EXPECT_EQ(mesh.vertices[2], Vec3(-2, 2000000, 252));
    EXPECT_EQ(mesh.triangles, (std::vector<TriIndices>{{2, 0, 1}}));
}

TEST(PlyErrors, HeaderProblemsNameTheFile) {
    const auto error_of = [](std::string_view text) {
        return input_error([&] { parse_ply(as_bytes(text), "h.ply"); });
    };
    EXPECT_THAT(error_of("PLY?\n"), HasSubstr("h.ply: header line 1: not a PLY file"));
    EXPECT_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 1\n"),
                HasSubstr("h.ply: header line 3: file ends before end_header"));
    EXPECT_THAT(error_of("ply\nformat binary_middle_endian 1.0\nend_header\n"), HasSubstr("unknown format"));
    EXPECT_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                         "end_header\n0 0\n"),
                HasSubstr("h.ply: vertex element has no property 'z'"));
    EXPECT_THAT(error_of("ply\nformat ascii 1.0\nelement face 0\nend_header\n"), HasSubstr("no vertex element"));
    EXPECT_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n"),
                HasSubstr("h.ply: header line 4: unknown property type 'quad'"));
}

constexpr std::string_view k_ascii_header =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST(PlyErrors, FaceProblemsNameTheFace) {
    const auto error_of = [](std::string_view faces) {
        const std::string text = std::string(k_ascii_header) + std::string(faces);
        return input_error([&] { parse_ply(as_bytes(text), "f.ply"); });
    };
    EXPECT_EQ(error_of("3 0 1 2\n3 0 1 9\n"), "f.ply: face 1: vertex index 9 out of range (4 vertices)");
    EXPECT_EQ(error_of("3 0 1 2\n3 0 -1 2\n"), "f.ply: face 1: vertex index -1 out of range (4 vertices)");
    EXPECT_THAT(error_of("2 0 1\n3 0 1 2\n"), HasSubstr("f.ply: face 0: 2 corners"));
    EXPECT_THAT(error_of("3 0 1 2\n3 0 1 2.5\n"), HasSubstr("f.ply: face 1: bad number '2.5'"));
}

TEST(PlyErrors, HugeCountsFailWithoutAllocating) {
    ByteWriter w;
    w.text("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
           "property float y\nproperty float z\nend_header\n");
    w.put(1.0f);
    EXPECT_EQ(input_error([&] { parse_ply(w.span(), "big.ply"); }),
              "big.ply: vertex 0: file truncated: expected 12 bytes at byte 124, the file ends at byte 128");
    const std::string text = std::string(k_ascii_header) + "200 0 1 2\n";
    EXPECT_EQ(input_error([&] { parse_ply(as_bytes(text), "l.ply"); }),
              "l.ply: face 0: file truncated: a list of 200 values does not fit in the 7 bytes left (line 14)");
}

}  // namespace
}  // namespace collidescope
