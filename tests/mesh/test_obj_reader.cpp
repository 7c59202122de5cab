// parse_obj: every face form, relative indices, fans, file order and sharing kept, and the
// malformed lines, each named by file and line.

#include "mesh/temp_files.hpp"

#include "collidescope/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

TEST(ObjReader, AllFaceFormsAndIgnoredRecords) {
    const std::string text =
        "# a comment\r\nmtllib x.mtl\r\no thing\r\ng group\r\ns 1\r\nusemtl red\r\n"
        "v 0 0 0\r\nv 1.5 0 0 1.0\r\nv\t0 +2 -0\r\nv 1e-3 1E3 0.1 0.5 0.5 0.5\r\n"
        "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\nvp 0.5\r\n"
        "f 1 2 3\r\nf 1/1 2/2 4/1\r\nf 2//1 3//1 4//1\r\nf 4/2/1 3/1/1 1/2/1\r\n"
        "l 1 2\r\n";
    const MeshData mesh = parse_obj(text, "forms.obj");
    ASSERT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.vertices[1], Vec3(1.5, 0, 0));
    EXPECT_EQ(mesh.vertices[2], Vec3(0, 2, 0));
    EXPECT_EQ(mesh.vertices[3], Vec3(1e-3, 1e3, 0.1));
    const std::vector<TriIndices> expected = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {3, 2, 0}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(ObjReader, NegativeIndicesCountBackFromTheLastVertex) {
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nf -1/-1/-1 -3//-2 -2/-4\n";
    const MeshData mesh = parse_obj(text, "neg.obj");
    const std::vector<TriIndices> expected = {{0, 1, 2}, {3, 1, 2}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(ObjReader, PolygonsSplitAsFansInFileOrder) {
    std::string text;
    for (int v = 0; v < 6; ++v) text += "v " + std::to_string(v) + " 0 0\n";
    text += "f 1 2 3 4\nf 6 5 4 3 2\nf 3 4 5\n";
    const MeshData mesh = parse_obj(text, "fan.obj");
    const std::vector<TriIndices> expected = {{0, 1, 2}, {0, 2, 3}, {5, 4, 3},
                                              {5, 3, 2}, {5, 2, 1}, {2, 3, 4}};
    EXPECT_EQ(mesh.triangles, expected);
}

TEST(ObjReader, StanfordBunnyKeepsVerticesAndSharing) {
    const std::filesystem::path bunny = "/usr/share/glmark2/models/bunny.obj";
    ASSERT_TRUE(std::filesystem::exists(bunny)) << bunny << " is not installed (apt-get install glmark2-data)";
    const MeshData mesh = read_mesh_file(bunny);
    EXPECT_EQ(mesh.vertices.size(), 34835u);
    ASSERT_EQ(mesh.triangles.size(), 69666u);
    EXPECT_EQ(mesh.vertices[0], Vec3(0.296502, -0.907931, 0.450151));
    EXPECT_EQ(mesh.triangles[0], (TriIndices{0, 1, 2}));
    EXPECT_EQ(mesh.triangles[1], (TriIndices{3, 4, 5}));
    // Every vertex is used, by about six triangles: the file's sharing survives.
    std::vector<int> uses(mesh.vertices.size(), 0);
    for (const TriIndices& triangle : mesh.triangles) {
        for (const std::uint32_t corner : triangle) ++uses[corner];
    }
    EXPECT_EQ(std::count(uses.begin(), uses.end(), 0), 0);
}

TEST(ObjErrors, MalformedLinesNameFileAndLine) {
    const auto error_of = [](const std::string& tail) {
        const std::string text = "v 0 0 0\nv 1 0 0\n# comment\nv 0 1 0\n" + tail;
        return input_error([&] { parse_obj(text, "bad.obj"); });
    };
    EXPECT_EQ(error_of("v 1 2\n"), "bad.obj: line 5: vertex needs 3 coordinates");
    EXPECT_EQ(error_of("v 1 abc 2\n"), "bad.obj: line 5: bad number 'abc'");
    EXPECT_EQ(error_of("v 1 2 3x\n"), "bad.obj: line 5: bad number '3x'");
    EXPECT_EQ(error_of("f 1 x 3\n"), "bad.obj: line 5: bad face corner 'x'");
    EXPECT_EQ(error_of("f 1 2a 3\n"), "bad.obj: line 5: bad face corner '2a'");
    EXPECT_EQ(error_of("f 1 2 0\n"), "bad.obj: line 5: vertex index 0 (OBJ indices start at 1)");
    EXPECT_EQ(error_of("f 1 2\n"), "bad.obj: line 5: face with 2 corners (a face needs at least 3)");
    EXPECT_EQ(error_of("\nf 1 2 9000\n"),
              "bad.obj: line 6: vertex index 9000 out of range (3 vertices defined before this line)");
    EXPECT_EQ(error_of("f 1 2 -4\n"),
              "bad.obj: line 5: vertex index -4 out of range (3 vertices defined before this line)");
}

TEST(ObjErrors, NonFiniteCoordinatesAreCaughtByValidation) {
    TempDir dir;
    write_text(dir / "nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    write_text(dir / "inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n");
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "nan.obj"); }),
                HasSubstr("nan.obj: vertex 1: coordinate y is not finite"));
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "inf.obj"); }),
                HasSubstr("inf.obj: vertex 2: coordinate z is not finite"));
}

}  // namespace
}  // namespace collidescope
