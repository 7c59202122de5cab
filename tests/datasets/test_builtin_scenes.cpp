// The built-in scene registry and the demo scene.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

TEST(BuiltinScenes, RegistryListsTheDataSetsAndDemo) {
    EXPECT_EQ(builtin_scene_names(),
              (std::vector<std::string>{"A", "B", "C", "D", "E1", "E2", "E3", "E4", "demo",
                                        "cloth-rest", "cloth-drape", "cloth-crumple", "cloth-slide", "contact-layers",
                                        "contact-spheres", "contact-rods", "contact-rollers", "coplanar-stack"}));
    EXPECT_EQ(builtin_scene_presets("demo"), (std::vector<std::string>{"default", "small"}));
    EXPECT_EQ(builtin_scene_presets("C"), (std::vector<std::string>{"default", "small", "large"}));
}

TEST(BuiltinScenes, AliasesNameTheSameScenes) {
    EXPECT_EQ(builtin_scene_presets("cloths"), builtin_scene_presets("B"));
    const Scene by_alias = make_builtin_scene("sine-sheets:small");
    const Scene by_name = make_builtin_scene("C:small");
    EXPECT_EQ(by_alias.name, "C");
    EXPECT_EQ(by_alias.source->frame(3).objects[1].vertices, by_name.source->frame(3).objects[1].vertices);
}

TEST(BuiltinScenes, UnknownNameOrPresetListsTheKnownOnes) {
    try {
        make_builtin_scene("nope");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("demo"), std::string::npos) << error.what();
    }
    try {
        make_builtin_scene("demo:huge");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("small"), std::string::npos) << error.what();
    }
    EXPECT_THROW(builtin_scene_presets("nope"), InputError);
}

TEST(BuiltinScenes, DemoDefaultPresetSizes) {
    const Scene scene = make_builtin_scene("demo");
    EXPECT_EQ(scene.name, "demo");
    EXPECT_EQ(scene.preset, "default");
    EXPECT_FALSE(scene.self_collision);
    EXPECT_EQ(scene.source->frame_count(), 60u);
    ASSERT_EQ(scene.source->object_count(), 2u);
    EXPECT_EQ(scene.source->object_name(0), "torus");
    const Frame frame = scene.source->frame(0);
    EXPECT_EQ(frame.objects[0].triangle_count() + frame.objects[1].triangle_count(), 4352u);
}

TEST(BuiltinScenes, DemoIsDeterministicAndKeepsItsTopology) {
    const Scene a = make_builtin_scene("demo:small");
    const Scene b = make_builtin_scene("demo:small");
    const Frame first = a.source->frame(0);
    for (std::uint32_t f = 0; f < a.source->frame_count(); ++f) {
        const Frame fa = a.source->frame(f);
        const Frame fb = b.source->frame(f);
        for (std::size_t o = 0; o < fa.objects.size(); ++o) {
            EXPECT_EQ(fa.objects[o].vertices, fb.objects[o].vertices);
            EXPECT_EQ(fa.objects[o].topology, first.objects[o].topology);  // deforms, never changes topology
        }
    }
}

TEST(BuiltinScenes, DemoHasFramesWithAndWithoutCollisions) {
    const Scene scene = make_builtin_scene("demo:small");
    Pipeline pipeline({"brute", false, 0});
    std::uint32_t colliding_frames = 0;
    for (const Frame& frame : testing::all_frames(scene)) {
        const FrameResult result = pipeline.process(frame);
        EXPECT_EQ(result.colliding_pairs, testing::reference_colliding_pairs(frame, false)) << "frame " << frame.index;
        colliding_frames += result.colliding_pairs.empty() ? 0 : 1;
    }
    EXPECT_GT(colliding_frames, 0u);
    EXPECT_LT(colliding_frames, scene.source->frame_count());
}

}  // namespace
}  // namespace collidescope
