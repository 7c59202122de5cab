// What read_with_assimp checks around assimp: an OFF header whose counts its file cannot
// hold is refused before assimp allocates them (plain and gzipped), a scene with a null node
// (assimp's RAW importer with two groups) is refused before it is walked, and the files that
// are fine still load.

#include "mesh/temp_files.hpp"

#include "collidescope/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <chrono>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

constexpr const char* k_cube_body =
    "-0.5 -0.5 0.5\n0.5 -0.5 0.5\n-0.5 0.5 0.5\n0.5 0.5 0.5\n"
    "-0.5 0.5 -0.5\n0.5 0.5 -0.5\n-0.5 -0.5 -0.5\n0.5 -0.5 -0.5\n"
    "4 0 1 3 2\n4 2 3 5 4\n4 4 5 7 6\n4 6 7 1 0\n4 1 7 5 3\n4 6 0 2 4\n";

void write_gzip(const std::filesystem::path& file, const std::string& text) {
    gzFile out = gzopen(file.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    ASSERT_EQ(gzwrite(out, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
    gzclose(out);
}

TEST(AssimpChecks, OffCountsThatTheFileCannotHoldAreRefusedAtOnce) {
    TempDir dir;
    // invalid/OutOfMemory.off of assimp-testmodels: 353535235358 vertices declared.
    const std::string lying = std::string("OFF\n353535235358 6 0\n") + k_cube_body;
    write_text(dir / "lying.off", lying);
    write_gzip(dir / "lying.off.gz", lying);
    const auto start = std::chrono::steady_clock::now();
    const std::string body_bytes = std::to_string(std::string(k_cube_body).size() + 3);  // " 0\n" + body
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "lying.off"); }),
              (dir / "lying.off").string() + ": header: 353535235358 vertices and 6 faces cannot fit in the " +
                  body_bytes + " bytes after the counts (each takes a line of at least 2 bytes)");
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "lying.off.gz"); }),
                HasSubstr("lying.off.gz: header: 353535235358 vertices and 6 faces cannot fit"));
    // Counts that fit 32 bits but not the file, after comments.
    write_text(dir / "faces.off", std::string("# a comment\nOFF # another\n8 600 0\n") + k_cube_body);
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "faces.off"); }),
                HasSubstr("faces.off: header: 8 vertices and 600 faces cannot fit"));
    // No keyword: assimp takes the first numbers as the counts.
    write_text(dir / "bare.off", std::string("353535235358 6 0\n") + k_cube_body);
    EXPECT_THAT(input_error([&] { read_mesh_file(dir / "bare.off"); }),
                HasSubstr("bare.off: header: 353535235358 vertices and 6 faces cannot fit"));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(AssimpChecks, OffFilesThatFitStillLoad) {
    TempDir dir;
    write_text(dir / "cube.off", std::string("OFF\n8 6 0\n") + k_cube_body);
    write_gzip(dir / "cube.off.gz", std::string("OFF\n8 6 0\n") + k_cube_body);
    write_text(dir / "coff.off", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n");
    for (const char* name : {"cube.off", "cube.off.gz"}) {
        const MeshData mesh = read_mesh_file(dir / name);
        EXPECT_EQ(mesh.vertices.size(), 8u) << name;
        EXPECT_EQ(mesh.triangles.size(), 12u) << name;
    }
    EXPECT_EQ(read_mesh_file(dir / "coff.off").triangles.size(), 1u);
    // The tightest file: one-character numbers, no line end after the last face.
    write_text(dir / "tight.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
    EXPECT_EQ(read_mesh_file(dir / "tight.off").vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST(AssimpChecks, ASceneWithANullNodeIsRefusedNotWalked) {
    TempDir dir;
    // assimp 5.2's RAW importer leaves the second of two groups' nodes null (RAW/WithColor.raw).
    write_text(dir / "two.raw", "a\n0 0 0 1 0 0 0 1 0\n\nb\n0 0 1 1 0 1 0 1 1\n");
    EXPECT_EQ(input_error([&] { read_mesh_file(dir / "two.raw"); }),
              (dir / "two.raw").string() + ": assimp returned a broken scene: node '<RawRoot>': children 1 of 2 is null");
    write_text(dir / "one.raw", "a\n0 0 0 1 0 0 0 1 0\n");
    EXPECT_EQ(read_mesh_file(dir / "one.raw").triangles.size(), 1u);
}

}  // namespace
}  // namespace collidescope
