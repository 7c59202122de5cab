// open_inputs on animated model files: frame count floor(duration * fps) + 1, frame k posed at
// k / fps seconds, one object per mesh instance, --clip and --fps, the scene's time fields and
// up axis, manifests with top-level "fps"/"clip", and the bad inputs.

#include "mesh/temp_files.hpp"
#include "support/reference_pose.hpp"
#include "support/testmodels.hpp"
#include "support/tiny_rig.hpp"

#include "collidescope/scene.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

using ::testing::HasSubstr;
using testing::write_tiny_rig;
using testing_files::TempDir;
using testing_files::write_text;

Scene open(const std::filesystem::path& file, AnimationOptions options = {}) {
    const std::vector<std::string> inputs{file.string()};
    return open_inputs(inputs, options);
}

std::string error_of(const std::vector<std::string>& inputs, AnimationOptions options = {}) {
    try {
        open_inputs(inputs, options);
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(AnimatedInputs, TinyRigFramesAreThePoseAtKOverFps) {
    TempDir dir;
    const auto file = dir.path() / "rig.assbin";
    write_tiny_rig(file);
    const Scene scene = open(file, {.fps = 4.0, .clip = std::nullopt});
    ASSERT_EQ(scene.source->frame_count(), 5u);  // 1 s at 4 fps: frames 0..4
    ASSERT_EQ(scene.source->object_count(), 1u);
    EXPECT_EQ(scene.source->object_name(0), "body/mesh0");
    EXPECT_EQ(scene.fps, 4.0);
    EXPECT_EQ(scene.clip, "rise");
    EXPECT_EQ(scene.frame_times, (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    for (std::uint32_t k = 0; k < 5; ++k) {
        const Frame frame = scene.source->frame(k);
        ASSERT_EQ(frame.objects[0].vertices.size(), 4u);
        EXPECT_EQ(frame.objects[0].vertices[2], Vec3(1, 1, 2 * k / 4.0)) << "frame " << k;
        EXPECT_EQ(frame.objects[0].topology->revision, scene.source->frame(0).objects[0].topology->revision);
    }
}

TEST(AnimatedInputs, DefaultsAreThirtyFpsAndTheFirstClip) {
    TempDir dir;
    const auto file = dir.path() / "rig.assbin";
    write_tiny_rig(file, {.second_clip = true});
    const Scene scene = open(file);
    EXPECT_EQ(scene.source->frame_count(), 31u);
    EXPECT_EQ(scene.clip, "rise");
    const Scene idle = open(file, {.fps = std::nullopt, .clip = "idle"});
    EXPECT_EQ(idle.clip, "idle");
    EXPECT_EQ(idle.source->frame_count(), 16u);  // 0.5 s at 30 fps
    EXPECT_EQ(idle.source->frame(15).objects[0].vertices[2], Vec3(1, 1, 0));
    EXPECT_EQ(open(file, {.fps = std::nullopt, .clip = "1"}).clip, "idle");
}

TEST(AnimatedInputs, MissingOrOutOfRangeClipIsAnErrorListingTheClips) {
    TempDir dir;
    const auto file = dir.path() / "rig.assbin";
    write_tiny_rig(file, {.second_clip = true});
    EXPECT_THAT(error_of({file.string()}, {.fps = std::nullopt, .clip = "walk"}),
                HasSubstr(file.string() + ": no clip 'walk' (clips: 0 'rise', 1 'idle')"));
    EXPECT_THAT(error_of({file.string()}, {.fps = std::nullopt, .clip = "2"}), HasSubstr(": no clip '2'"));
}

TEST(AnimatedInputs, ManifestTopLevelFpsAndClipAndTheCommandLineWins) {
    TempDir dir;
    write_tiny_rig(dir.path() / "rig.assbin", {.second_clip = true});
    const auto manifest = dir.path() / "scene.json";
    write_text(manifest, R"({"fps": 10, "clip": "idle", "objects": [{"name": "hand", "pattern": "rig.assbin"}]})");
    const std::vector<std::string> inputs{manifest.string()};
    const Scene scene = open_inputs(inputs);
    EXPECT_EQ(scene.fps, 10);
    EXPECT_EQ(scene.clip, "idle");
    EXPECT_EQ(scene.source->frame_count(), 6u);
    EXPECT_EQ(scene.source->object_name(0), "hand/body/mesh0");
    const Scene overridden = open_inputs(inputs, {.fps = 2.0, .clip = "0"});
    EXPECT_EQ(overridden.clip, "rise");
    EXPECT_EQ(overridden.source->frame_count(), 3u);
    write_text(manifest, R"({"fps": -1, "objects": [{"pattern": "rig.assbin"}]})");
    EXPECT_THAT(error_of(inputs), HasSubstr("scene.json: fps: expected a positive number, got number -1"));
}

TEST(AnimatedInputs, BadRigsFailAtOpenWithOneLine) {
    TempDir dir;
    const auto file = dir.path() / "nan.assbin";
    write_tiny_rig(file, {.nan_key = true});
    const std::string message = error_of({file.string()});
    EXPECT_THAT(message, HasSubstr(file.string()));
    EXPECT_THAT(message, HasSubstr("not finite"));
    EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(AnimatedInputs, BcnEpilepticFramesEqualTheReferenceAtKOverFps) {
    REQUIRE_TESTMODEL(file, "X/BCN_Epileptic.X");
    const Scene scene = open(file, {.fps = 5.0, .clip = std::nullopt});
    Assimp::Importer importer;
    const aiScene* ai = importer.ReadFile(file.string(), 0);
    ASSERT_NE(ai, nullptr);
    const aiAnimation& clip = *ai->mAnimations[0];
    // 15,840 ticks at 4,800 per second: 3.3 s, frames 0..16 at 5 fps.
    EXPECT_EQ(scene.source->frame_count(),
              static_cast<std::uint32_t>(std::floor(clip.mDuration / clip.mTicksPerSecond * 5 + 1e-9)) + 1);
    EXPECT_EQ(scene.clip, "Epileptisch");
    EXPECT_EQ(scene.name, "BCN_Epileptic");
    EXPECT_EQ(scene.up_axis, 0);  // .X says nothing
    for (const std::uint32_t k : {0u, 7u, scene.source->frame_count() - 1}) {
        const Frame frame = scene.source->frame(k);
        const auto expected = reference::pose(*ai, 0, k / 5.0 * clip.mTicksPerSecond);
        ASSERT_EQ(frame.objects.size(), expected.size());
        for (std::size_t o = 0; o < expected.size(); ++o) {
            EXPECT_EQ(scene.source->object_name(static_cast<std::uint32_t>(o)), expected[o].name);
            const auto& triangles = frame.objects[o].topology->triangles;
            ASSERT_EQ(triangles.size(), expected[o].triangles.size());
            double worst = 0;
            for (std::size_t t = 0; t < triangles.size(); ++t) {
                for (int c = 0; c < 3; ++c) {
                    const Vec3 d = frame.objects[o].vertices[triangles[t][c]] -
                                   expected[o].vertices[expected[o].triangles[t][c]];
                    worst = std::max(worst, d.cwiseAbs().maxCoeff());
                }
            }
            EXPECT_LT(worst, 1e-9 * 100) << expected[o].name << " frame " << k;
        }
    }
}

TEST(AnimatedInputs, GltfSaysYUp) {
    REQUIRE_TESTMODEL(file, "glTF2/simple_skin/simple_skin.gltf");
    const Scene scene = open(file);
    EXPECT_EQ(scene.up_axis, 'y');
    EXPECT_EQ(scene.source->frame_count(), static_cast<std::uint32_t>(std::floor(5.5 * 30)) + 1);
}

TEST(AnimatedInputs, FbxUpAxisComesFromItsGlobalSettingsAlsoForAStaticFile) {
    REQUIRE_TESTMODEL(animated, "FBX/animation_with_skeleton.fbx");
    EXPECT_EQ(open(animated).up_axis, 'y');  // UpAxis 1 in the file's GlobalSettings
    REQUIRE_TESTMODEL(still, "FBX/box.fbx");
    const Scene scene = open(still);
    EXPECT_EQ(scene.source->frame_count(), 1u);
    EXPECT_EQ(scene.up_axis, 'y');
    EXPECT_TRUE(scene.frame_times.empty());
    EXPECT_EQ(scene.fps, 0);
}

TEST(AnimatedInputs, AnimTestXBoneNamingNoNodeFailsAtOpen) {
    REQUIRE_TESTMODEL(file, "X/anim_test.x");
    const std::string message = error_of({file.string()});
    EXPECT_THAT(message, HasSubstr(file.string() + ": mesh 0 'pCylinder1' bone "));
    EXPECT_THAT(message, HasSubstr("names no node"));
}

}  // namespace
}  // namespace collidescope
