// Mesh + point cache objects in open_inputs: `mesh@cache` on the command line and
// {"mesh", "cache"} in a scene.json give the cache's frames on the mesh's triangles, the same
// frames as the motion written as a frame sequence; the scene takes the cache's times; a
// vertex count that differs names both files and both counts.

#include "mesh/temp_files.hpp"
#include "support/cli_runner.hpp"
#include "support/point_cache_writer.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace collidescope {
namespace {

using namespace testing_files;
using testing::PositionFrames;
using ::testing::HasSubstr;

Scene open_cached(std::vector<std::string> inputs) { return open_inputs(inputs); }

// The demo scene's frames of one object, and their positions as float32 (what the files hold).
struct ObjectMotion {
    MeshData mesh;           ///< frame 0, float32
    PositionFrames frames;   ///< every frame's positions, float32
};

ObjectMotion motion_of(const Scene& scene, std::uint32_t object) {
    ObjectMotion motion;
    for (const Frame& frame : testing::all_frames(scene)) {
        std::vector<Vec3> positions;
        for (const Vec3& v : frame.objects[object].vertices) positions.push_back(round_to_float32(v));
        motion.frames.push_back(std::move(positions));
    }
    const Frame first = scene.source->frame(0);
    motion.mesh.triangles = first.objects[object].topology->triangles;
    motion.mesh.vertices = motion.frames.front();
    return motion;
}

void expect_same_frames(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.source->frame_count(), b.source->frame_count());
    ASSERT_EQ(a.source->object_count(), b.source->object_count());
    for (std::uint32_t k = 0; k < a.source->frame_count(); ++k) {
        const Frame fa = a.source->frame(k);
        const Frame fb = b.source->frame(k);
        for (std::size_t o = 0; o < fa.objects.size(); ++o) {
            EXPECT_EQ(fa.objects[o].topology->triangles, fb.objects[o].topology->triangles) << "frame " << k;
            EXPECT_EQ(fa.objects[o].vertices, fb.objects[o].vertices) << "frame " << k << " object " << o;
        }
    }
}

TEST(PointCacheInputs, CachesGiveTheFramesOfTheSequence) {
    TempDir dir;
    const Scene demo = make_builtin_scene("demo:small");
    const std::vector<std::string> patterns = testing::write_scene_files(demo, dir.path());
    const ObjectMotion torus = motion_of(demo, 0);
    const ObjectMotion sheet = motion_of(demo, 1);
    write_ply(dir / "torus.ply", torus.mesh);
    write_ply(dir / "sheet.ply", sheet.mesh);
    testing::write_pc2(dir / "torus.pc2", torus.frames);
    std::vector<float> times;
    for (std::size_t k = 0; k < sheet.frames.size(); ++k) times.push_back(static_cast<float>(k) / 24.0f);
    testing::write_mdd(dir / "sheet.mdd", sheet.frames, times);

    const Scene sequence = open_cached(patterns);
    const Scene cached = open_cached({(dir / "torus.ply").string() + "@" + (dir / "torus.pc2").string(),
                               (dir / "sheet.ply").string() + "@" + (dir / "sheet.mdd").string()});
    expect_same_frames(sequence, cached);
    EXPECT_EQ(cached.source->object_name(0), "torus");
    EXPECT_EQ(cached.source->object_name(1), "sheet");
    // The first cache's times: PC2 at 30 frames per second.
    ASSERT_EQ(cached.frame_times.size(), demo.source->frame_count());
    EXPECT_DOUBLE_EQ(cached.frame_times[3], 0.1);
    EXPECT_DOUBLE_EQ(cached.fps, 30.0);
    EXPECT_TRUE(sequence.frame_times.empty());

    write_text(dir / "scene.json", R"({"name": "demo", "objects": [
        {"name": "ring", "mesh": "torus.ply", "cache": "torus.pc2"},
        {"mesh": "sheet.ply", "cache": "sheet.mdd"}]})");
    const Scene manifest = open_cached({(dir / "scene.json").string()});
    expect_same_frames(sequence, manifest);
    EXPECT_EQ(manifest.source->object_name(0), "ring");
    EXPECT_EQ(manifest.name, "demo");
}

TEST(PointCacheInputs, ManifestFramesTakeTheFirstFramesOfTheCache) {
    TempDir dir;
    const MeshData sheet = testing::grid_sheet(2, 1.0);
    PositionFrames frames(5, sheet.vertices);
    for (std::size_t k = 0; k < frames.size(); ++k) frames[k][0].z() = static_cast<double>(k);
    write_ply(dir / "sheet.ply", sheet);
    testing::write_mdd(dir / "sheet.mdd", frames, {0.0f, 0.5f, 1.0f, 1.5f, 2.0f});
    write_text(dir / "scene.json", R"({"frames": 3, "objects": [{"mesh": "sheet.ply", "cache": "sheet.mdd"}]})");
    const Scene scene = open_cached({(dir / "scene.json").string()});
    ASSERT_EQ(scene.source->frame_count(), 3u);
    EXPECT_EQ(scene.frame_times, (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_DOUBLE_EQ(scene.fps, 2.0);
    EXPECT_EQ(scene.source->frame(2).objects[0].vertices[0].z(), 2.0);

    write_text(dir / "long.json", R"({"frames": 6, "objects": [{"mesh": "sheet.ply", "cache": "sheet.mdd"}]})");
    EXPECT_THAT(input_error([&] { open_cached({(dir / "long.json").string()}); }),
                HasSubstr("frames: asks for 6 frames but object 'sheet'"));
}

TEST(PointCacheInputsErrors, VertexCountsThatDifferNameBothFiles) {
    TempDir dir;
    const MeshData sheet = testing::grid_sheet(2, 1.0);  // 9 vertices
    write_ply(dir / "sheet.ply", sheet);
    testing::write_pc2(dir / "short.pc2", PositionFrames(2, std::vector<Vec3>(8, Vec3::Zero())));
    const std::string mesh = (dir / "sheet.ply").string();
    const std::string cache = (dir / "short.pc2").string();
    const Scene scene = open_cached({mesh + "@" + cache});
    EXPECT_EQ(input_error([&] { scene.source->frame(0); }),
              mesh + " has 9 vertices but its point cache " + cache + " has 8 points per frame (object 'sheet')");
}

TEST(PointCacheInputsErrors, BadCachesAndMeshes) {
    TempDir dir;
    const MeshData sheet = testing::grid_sheet(1, 1.0);  // 4 vertices
    write_ply(dir / "sheet.ply", sheet);
    PositionFrames frames(3, sheet.vertices);
    frames[2][1].x() = std::numeric_limits<double>::quiet_NaN();
    testing::write_pc2(dir / "nan.pc2", frames);
    const std::string mesh = (dir / "sheet.ply").string();
    const std::string nan = (dir / "nan.pc2").string();
    const Scene scene = open_cached({mesh + "@" + nan});
    scene.source->frame(1);
    EXPECT_EQ(input_error([&] { scene.source->frame(2); }),
              nan + ": frame 2, vertex 1: coordinate x is not finite (nan) (object 'sheet')");

    const std::string missing_cache = (dir / "missing.mdd").string();
    EXPECT_EQ(input_error([&] { open_cached({mesh + "@" + missing_cache}); }), missing_cache + ": no such file");
    const std::string missing_mesh = (dir / "missing.ply").string();
    EXPECT_EQ(input_error([&] { open_cached({missing_mesh + "@" + nan}); }),
              missing_mesh + ": no such file (the mesh of point cache " + nan + ")");
    const std::string pattern = (dir / "sheet.%d.ply").string();
    EXPECT_THAT(input_error([&] { open_cached({pattern + "@" + nan}); }),
                HasSubstr(pattern + ": a point cache needs one mesh file, not a frame pattern"));

    const std::string manifest = (dir / "scene.json").string();
    write_text(manifest, R"({"objects": [{"pattern": "sheet.ply", "cache": "nan.pc2"}]})");
    EXPECT_EQ(input_error([&] { open_cached({manifest}); }),
              manifest + ": objects[0].cache: needs \"mesh\": the mesh file whose vertices the cache moves");
    write_text(manifest, R"({"objects": [{"pattern": "sheet.ply", "mesh": "sheet.ply"}]})");
    EXPECT_EQ(input_error([&] { open_cached({manifest}); }), manifest + ": objects[0]: give either \"pattern\" or \"mesh\", not both");
    write_text(manifest, R"({"objects": [{"mesh": "sheet.ply", "cache": 3}]})");
    EXPECT_EQ(input_error([&] { open_cached({manifest}); }), manifest + ": objects[0].cache: expected a string, got number 3");
}

TEST(PointCacheInputs, AnExistingFileWithAnAtIsAFile) {
    TempDir dir;
    write_ply(dir / "a@b.pc2.ply", testing::grid_sheet(1, 1.0));
    const Scene scene = open_cached({(dir / "a@b.pc2.ply").string()});
    EXPECT_EQ(scene.source->frame_count(), 1u);
    // Not a point cache after the '@': an ordinary (missing) file.
    const std::string other = (dir / "x@y.ply").string();
    EXPECT_EQ(input_error([&] { open_cached({other}); }), other + ": no such file");
}

}  // namespace
}  // namespace collidescope
