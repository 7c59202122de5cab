// The file-backed FrameSource: lazy reads, topology shared while triangles stay equal and a
// new revision when they change, and errors that name the file, object and frame.

#include "mesh/temp_files.hpp"

#include "collidescope/scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

MeshData strip(int triangles, double lift) {
    MeshData mesh;
    for (int i = 0; i < triangles + 2; ++i) mesh.vertices.emplace_back(i / 2, i % 2, lift);
    for (std::uint32_t t = 0; t < static_cast<std::uint32_t>(triangles); ++t) mesh.triangles.push_back({t, t + 1, t + 2});
    return mesh;
}

std::string frame_file(const TempDir& dir, const std::string& stem, int frame) {
    return (dir / numbered_name(stem + ".", frame, ".ply")).string();
}

TEST(FileSource, TopologySharedUntilTrianglesChange) {
    TempDir dir;
    // Frames 0-2: same triangles, moving vertices; frame 3: one more triangle (a fracture);
    // frame 4: back to the first triangles (a new revision all the same: it changed).
    const int triangle_counts[5] = {3, 3, 3, 4, 3};
    for (int frame = 0; frame < 5; ++frame) write_ply(frame_file(dir, "s", frame), strip(triangle_counts[frame], frame));
    const std::vector<std::string> inputs = {(dir / "s.%d.ply").string()};
    const Scene scene = open_inputs(inputs);
    std::vector<Frame> frames;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) frames.push_back(scene.source->frame(f));
    const auto topology = [&](int f) { return frames[f].objects[0].topology; };
    EXPECT_EQ(topology(0), topology(1));
    EXPECT_EQ(topology(1), topology(2));
    EXPECT_NE(topology(2)->revision, topology(3)->revision);
    EXPECT_GT(topology(3)->revision, topology(2)->revision);
    EXPECT_NE(topology(3)->revision, topology(4)->revision);
    EXPECT_EQ(topology(4)->triangles, topology(0)->triangles);
    EXPECT_EQ(frames[2].objects[0].vertices[0].z(), 2.0);
    for (const Frame& frame : frames) {
        EXPECT_EQ(frame.objects[0].vertices.size(), frame.objects[0].topology->vertex_count);
    }
}

TEST(FileSource, RevisionsAreUniqueAcrossObjects) {
    TempDir dir;
    for (int frame = 0; frame < 2; ++frame) {
        write_ply(frame_file(dir, "a", frame), strip(3, frame));
        write_ply(frame_file(dir, "b", frame), strip(3, -frame));
    }
    write_ply(dir / "c.ply", strip(3, 9));
    const std::vector<std::string> inputs = {(dir / "a.%d.ply").string(), (dir / "b.%d.ply").string(),
                                             (dir / "c.ply").string()};
    const Scene scene = open_inputs(inputs);
    const Frame frame = scene.source->frame(1);
    std::set<std::uint64_t> revisions;
    for (const ObjectFrame& object : frame.objects) revisions.insert(object.topology->revision);
    EXPECT_EQ(revisions.size(), 3u);
    EXPECT_EQ(revisions.count(0), 0u);
}

TEST(FileSource, ReadsLazilyAndNamesTheFrameOfABadFile) {
    TempDir dir;
    for (int frame = 0; frame < 3; ++frame) write_ply(frame_file(dir, "cloth", frame), strip(2, frame));
    const std::string bad = frame_file(dir, "cloth", 2);
    std::vector<std::byte> bytes = read_file_bytes(bad);
    bytes.resize(bytes.size() - 2 * 13 - 20);  // all faces and part of vertex 2
    write_bytes(bad, bytes);
    const std::vector<std::string> inputs = {(dir / "cloth.%d.ply").string()};
    const Scene scene = open_inputs(inputs);
    ASSERT_EQ(scene.source->frame_count(), 3u);
    for (const int f : {0, 1}) {  // the good frames read back exactly what was written
        const Frame frame = scene.source->frame(static_cast<std::uint32_t>(f));
        const MeshData written = strip(2, f);
        ASSERT_EQ(frame.objects.size(), 1u);
        EXPECT_EQ(frame.objects[0].topology->triangles, written.triangles) << "frame " << f;
        ASSERT_EQ(frame.objects[0].vertices.size(), written.vertices.size()) << "frame " << f;
        for (std::size_t v = 0; v < written.vertices.size(); ++v) {
            EXPECT_EQ(frame.objects[0].vertices[v], written.vertices[v]) << "frame " << f << ", vertex " << v;
        }
    }
    EXPECT_EQ(input_error([&] { scene.source->frame(2); }),
              bad + ": vertex 2: file truncated: expected 12 bytes at byte 225, the file ends at byte 229 (object 'cloth', "
                    "frame 2)");
    EXPECT_THROW(scene.source->frame(3), std::out_of_range);
}

TEST(FileSource, BadStaticFileNamesTheObject) {
    TempDir dir;
    write_text(dir / "wall.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
    const std::vector<std::string> inputs = {(dir / "wall.obj").string()};
    const Scene scene = open_inputs(inputs);
    EXPECT_EQ(input_error([&] { scene.source->frame(0); }),
              (dir / "wall.obj").string() +
                  ": line 3: vertex index 3 out of range (2 vertices defined before this line) (object 'wall')");
}

TEST(FileSource, IndexOutOfRangeInAFrameIsNamed) {
    TempDir dir;
    write_ply(frame_file(dir, "m", 0), strip(2, 0));
    MeshData broken = strip(2, 1);
    broken.triangles[1][2] = 40;
    write_ply(frame_file(dir, "m", 1), broken);
    const std::vector<std::string> inputs = {(dir / "m.%d.ply").string()};
    const Scene scene = open_inputs(inputs);
    EXPECT_EQ(input_error([&] { scene.source->frame(1); }),
              frame_file(dir, "m", 1) + ": face 1: vertex index 40 out of range (4 vertices) (object 'm', frame 1)");
}

}  // namespace
}  // namespace collidescope
