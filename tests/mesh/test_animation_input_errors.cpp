// Bad animated input: one-line InputErrors naming the file and the element.

#include "mesh/temp_files.hpp"
#include "support/tiny_rig.hpp"

#include "mesh/animated_model.hpp"
#include "mesh/animation_clip.hpp"
#include "mesh/model_pose.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace collidescope {
namespace {

using ::testing::HasSubstr;
using testing::TinyRigOptions;
using testing::write_tiny_rig;
using testing_files::TempDir;

std::string error_of(const std::filesystem::path& file) {
    try {
        animation::read_animated_model(file);
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(AnimationInputErrors, NanKeyNamesClipChannelAndKey) {
    TempDir dir;
    const auto file = dir.path() / "nan.assbin";
    write_tiny_rig(file, {.nan_key = true});
    const std::string message = error_of(file);
    EXPECT_THAT(message, HasSubstr(file.string()));
    EXPECT_THAT(message, HasSubstr("clip 0 'rise' channel 0 'arm' position key 1: value is not finite"));
}

TEST(AnimationInputErrors, ZeroWeightsEverywhereNameTheMesh) {
    TempDir dir;
    const auto file = dir.path() / "zero.assbin";
    write_tiny_rig(file, {.zero_weights = true});
    EXPECT_THAT(error_of(file), HasSubstr(file.string() + ": mesh 0: every bone weight is zero"));
}

TEST(AnimationInputErrors, BoneNamingNoNode) {
    TempDir dir;
    const auto file = dir.path() / "elbow.assbin";
    write_tiny_rig(file, {.unknown_bone = true});
    EXPECT_THAT(error_of(file), HasSubstr(file.string() + ": mesh 0 bone 0 'elbow' names no node"));
}

TEST(AnimationInputErrors, TheGoodRigReadsWeldedAndPosesExactly) {
    TempDir dir;
    const auto file = dir.path() / "rig.assbin";
    write_tiny_rig(file);
    const animation::AnimatedModel model = animation::read_animated_model(file);
    ASSERT_EQ(model.instances.size(), 1u);
    const animation::MeshInstance& quad = model.instances[0];
    EXPECT_EQ(quad.name, "body/mesh0");  // assbin keeps no mesh names
    EXPECT_EQ(quad.base.size(), 4u);  // vertex 4 welded onto vertex 2
    EXPECT_EQ(quad.triangles, (std::vector<TriIndices>{{0, 1, 2}, {0, 2, 3}}));
    animation::Pose pose;
    animation::PoseScratch scratch;
    std::vector<Vec3> vertices;
    for (const double ticks : {-3.0, 0.0, 2.5, 10.0, 40.0}) {
        animation::sample_clip(model, model.clips[0], ticks, pose);
        animation::pose_instance(quad, pose, scratch, vertices);
        const double z = 2 * std::clamp(ticks, 0.0, 10.0) / 10;
        EXPECT_EQ(vertices[2], Vec3(1, 1, z)) << "tick " << ticks;
    }
}

}  // namespace
}  // namespace collidescope
