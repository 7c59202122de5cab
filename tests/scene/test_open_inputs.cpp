// open_inputs: frame patterns (%04d, %d, ####), manifests, static + sequence mixes, and the
// bad inputs (patterns matching nothing, frame counts that differ, malformed scene.json).

#include "mesh/temp_files.hpp"

#include "collidescope/scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace collidescope {
namespace {

using namespace testing_files;
using ::testing::HasSubstr;

// Two triangles, shifted along x by `shift` so every frame's file differs.
MeshData frame_mesh(double shift) {
    MeshData mesh;
    mesh.vertices = {{shift, 0, 0}, {shift + 1, 0, 0}, {shift, 1, 0}, {shift + 1, 1, 0.5}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    return mesh;
}

void write_obj(const std::filesystem::path& file, const MeshData& mesh) {
    std::string text;
    for (const Vec3& v : mesh.vertices) {
        text += "v " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
    }
    for (const TriIndices& t : mesh.triangles) {
        text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    }
    write_text(file, text);
}

Scene open_scene(std::vector<std::string> inputs) { return open_inputs(inputs); }

TEST(OpenInputs, PrintfPatternTakesConsecutiveFramesFromTheFirst) {
    TempDir dir;
    for (int frame : {3, 4, 5}) {
        write_ply(dir / numbered_name("cloth.", frame, ".ply", 4), frame_mesh(frame));
    }
    write_ply(dir / "cloth.002.ply", frame_mesh(2));  // not what %04d writes
    write_ply(dir / "cloth.0002.obj.ply", frame_mesh(2));
    const Scene scene = open_scene({(dir / "cloth.%04d.ply").string()});
    ASSERT_EQ(scene.source->frame_count(), 3u);
    ASSERT_EQ(scene.source->object_count(), 1u);
    EXPECT_EQ(scene.source->object_name(0), "cloth");
    EXPECT_EQ(scene.name, "cloth");
    EXPECT_FALSE(scene.self_collision);
    const Frame frame = scene.source->frame(2);
    EXPECT_EQ(frame.index, 2u);
    EXPECT_EQ(frame.objects[0].vertices, frame_mesh(5).vertices);
}

TEST(OpenInputs, AGapInThePatternsFramesNamesTheMissingFile) {
    TempDir dir;
    for (int frame : {3, 4, 5, 7, 8}) write_ply(dir / numbered_name("cloth.", frame, ".ply", 4), frame_mesh(frame));
    try {
        open_scene({(dir / "cloth.%04d.ply").string()});
        FAIL() << "a gap in the frame numbers was accepted";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("cloth.0006.ply is missing"), std::string::npos) << message;
        EXPECT_NE(message.find("cloth.0008.ply exists"), std::string::npos) << message;
        EXPECT_NE(message.find("frames 3 to 8"), std::string::npos) << message;
    }
}

TEST(OpenInputs, HashAndPlainPrintfPatterns) {
    TempDir dir;
    for (int frame = 0; frame < 12; ++frame) {
        write_obj(dir / numbered_name("ball_", frame, ".obj"), frame_mesh(frame));
        write_obj(dir / numbered_name("box-", frame, ".obj", 3), frame_mesh(-frame));
    }
    write_obj(dir / "ball_012.obj", frame_mesh(12));  // %d never pads
    const Scene scene = open_scene({(dir / "ball_%d.obj").string(), (dir / "box-###.obj").string()});
    EXPECT_EQ(scene.source->frame_count(), 12u);
    EXPECT_EQ(scene.source->object_name(0), "ball");
    EXPECT_EQ(scene.source->object_name(1), "box");
    EXPECT_EQ(scene.name, "ball+box");
    const Frame frame = scene.source->frame(11);
    EXPECT_EQ(frame.objects[0].vertices[0].x(), 11.0);
    EXPECT_EQ(frame.objects[1].vertices[0].x(), -11.0);
}

TEST(OpenInputs, StaticFileRepeatsAlongASequence) {
    TempDir dir;
    for (int frame = 1; frame <= 4; ++frame) write_ply(dir / numbered_name("cloth.", frame, ".ply"), frame_mesh(frame));
    write_ply(dir / "floor.ply", frame_mesh(-5));
    const Scene scene = open_scene({(dir / "floor.ply").string(), (dir / "cloth.%d.ply").string()});
    ASSERT_EQ(scene.source->frame_count(), 4u);
    EXPECT_EQ(scene.source->object_name(0), "floor");
    const Frame first = scene.source->frame(0);
    const Frame last = scene.source->frame(3);
    EXPECT_EQ(first.objects[0].vertices, frame_mesh(-5).vertices);
    EXPECT_EQ(last.objects[0].vertices, frame_mesh(-5).vertices);
    EXPECT_EQ(first.objects[0].topology, last.objects[0].topology);
    EXPECT_EQ(last.objects[1].vertices, frame_mesh(4).vertices);
}

TEST(OpenInputs, StaticFilesAloneMakeOneFrame) {
    TempDir dir;
    write_ply(dir / "a.ply.gz.ply", frame_mesh(0));
    write_obj(dir / "b.obj", frame_mesh(1));
    const Scene scene = open_scene({(dir / "a.ply.gz.ply").string(), (dir / "b.obj").string()});
    EXPECT_EQ(scene.source->frame_count(), 1u);
    EXPECT_EQ(scene.source->object_name(0), "a.ply.gz");
    EXPECT_EQ(scene.source->frame(0).objects[1].vertices, frame_mesh(1).vertices);
}

TEST(OpenInputs, ManifestUsesItsNamesAndTheFirstFrames) {
    TempDir dir;
    std::filesystem::create_directory(dir / "cache");
    for (int frame = 0; frame < 5; ++frame) {
        write_ply(dir / numbered_name("cache/cloth.", frame, ".ply", 4), frame_mesh(frame));
        write_ply(dir / numbered_name("cache/body.", frame, ".ply", 4), frame_mesh(-frame));
    }
    write_text(dir / "scene.json",
               R"({"name": "drape", "frames": 3, "self": true, "objects": [
                   {"name": "sheet", "pattern": "cache/cloth.%04d.ply"},
                   {"pattern": "cache/body.####.ply"}]})");
    const Scene scene = open_scene({(dir / "scene.json").string()});
    EXPECT_EQ(scene.name, "drape");
    EXPECT_TRUE(scene.self_collision);
    EXPECT_EQ(scene.source->frame_count(), 3u);
    EXPECT_EQ(scene.source->object_name(0), "sheet");
    EXPECT_EQ(scene.source->object_name(1), "body");
    EXPECT_EQ(scene.source->frame(2).objects[1].vertices, frame_mesh(-2).vertices);
}

TEST(OpenInputs, ManifestWithoutOptionalKeys) {
    TempDir dir;
    for (int frame = 0; frame < 2; ++frame) write_ply(dir / numbered_name("m", frame, ".ply"), frame_mesh(frame));
    write_text(dir / "scene.json", R"({"objects": [{"pattern": "m%d.ply"}]})");
    const Scene scene = open_scene({(dir / "scene.json").string()});
    EXPECT_EQ(scene.name, dir.path().filename().string());
    EXPECT_FALSE(scene.self_collision);
    EXPECT_EQ(scene.source->frame_count(), 2u);
    EXPECT_EQ(scene.source->object_name(0), "m");
}

TEST(OpenInputsErrors, PatternsAndFilesThatMatchNothing) {
    TempDir dir;
    const std::string pattern = (dir / "cloth.%04d.ply").string();
    EXPECT_EQ(input_error([&] { open_scene({pattern}); }), pattern + ": no file matches this frame pattern");
    const std::string hashes = (dir / "nowhere/cloth.####.ply").string();
    EXPECT_EQ(input_error([&] { open_scene({hashes}); }), hashes + ": no file matches this frame pattern");
    const std::string file = (dir / "bunny.obj").string();
    EXPECT_EQ(input_error([&] { open_scene({file}); }), file + ": no such file");
    const std::string two_fields = (dir / "c.%04d.%d.ply").string();
    EXPECT_EQ(input_error([&] { open_scene({two_fields}); }), two_fields + ": more than one frame number field");
    EXPECT_THAT(input_error([&] { open_scene({}); }), HasSubstr("no input"));
}

TEST(OpenInputsErrors, SequencesOfDifferentLengths) {
    TempDir dir;
    for (int frame = 0; frame < 4; ++frame) write_ply(dir / numbered_name("a.", frame, ".ply"), frame_mesh(frame));
    for (int frame = 0; frame < 3; ++frame) write_ply(dir / numbered_name("b.", frame, ".ply"), frame_mesh(frame));
    const std::string a = (dir / "a.%d.ply").string();
    const std::string b = (dir / "b.%d.ply").string();
    EXPECT_EQ(input_error([&] { open_scene({a, b}); }),
              "objects 'a' (" + a + ": 4 frames) and 'b' (" + b + ": 3 frames) have different frame counts");
}

TEST(OpenInputsErrors, MalformedManifests) {
    TempDir dir;
    write_ply(dir / "m0.ply", frame_mesh(0));
    const std::string manifest = (dir / "scene.json").string();
    const auto error_of = [&](std::string_view json) {
        write_text(manifest, json);
        return input_error([&] { open_scene({manifest}); });
    };
    EXPECT_THAT(error_of(R"({"objects": [)"), HasSubstr(manifest + ": malformed JSON"));
    EXPECT_EQ(error_of(R"([1, 2])"), manifest + ": expected a JSON object at the top level");
    EXPECT_EQ(error_of(R"({"name": "x"})"), manifest + ": objects: missing key");
    EXPECT_EQ(error_of(R"({"objects": [{"name": "a"}]})"), manifest + ": objects[0].pattern: missing key (or \"mesh\")");
    EXPECT_EQ(error_of(R"({"objects": [{"pattern": 7}]})"),
              manifest + ": objects[0].pattern: expected a string, got number 7");
    EXPECT_EQ(error_of(R"({"frames": "ten", "objects": [{"pattern": "m%d.ply"}]})"),
              manifest + ": frames: expected a positive integer, got string \"ten\"");
    EXPECT_EQ(error_of(R"({"frames": 0, "objects": [{"pattern": "m%d.ply"}]})"),
              manifest + ": frames: expected a positive integer, got number 0");
    EXPECT_EQ(error_of(R"({"self": "yes", "objects": [{"pattern": "m%d.ply"}]})"),
              manifest + ": self: expected a boolean, got string \"yes\"");
    EXPECT_EQ(error_of(R"({"name": 3, "objects": [{"pattern": "m%d.ply"}]})"),
              manifest + ": name: expected a string, got number 3");
    EXPECT_EQ(error_of(R"({"objects": {}})"), manifest + ": objects: expected a non-empty array, got object {}");
    EXPECT_EQ(error_of(R"({"frames": 2, "objects": [{"name": "m", "pattern": "m%d.ply"}]})"),
              manifest + ": frames: asks for 2 frames but object 'm' (" + (dir / "m%d.ply").string() +
                  ") has 1");
    const std::string missing = (dir / "none.json").string();
    EXPECT_EQ(input_error([&] { open_scene({missing}); }), missing + ": no such file");
}

}  // namespace
}  // namespace collidescope
