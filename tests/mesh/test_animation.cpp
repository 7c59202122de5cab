// Animated models (mesh/animated_model, animation_clip, morph, skinning, model_pose) against
// the independent reference evaluation (support/reference_pose) on Debian's assimp-testmodels,
// at times before the first key, between keys, on the last and after it.

#include "support/reference_pose.hpp"
#include "support/testmodels.hpp"

#include "mesh/animated_model.hpp"
#include "mesh/animation_clip.hpp"
#include "mesh/model_pose.hpp"

#include "collidescope/error.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

using namespace animation;

struct Case {
    const char* file;
    bool skinned;  ///< has bones (else: morph targets or rigid nodes)
};

class AnimatedTestModel : public ::testing::TestWithParam<Case> {};

// Largest |coordinate| of a posed model: the scale of the comparison's tolerance.
double extent(const std::vector<reference::PosedInstance>& posed) {
    double scale = 1;
    for (const auto& instance : posed) {
        for (const Vec3& v : instance.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
    }
    return scale;
}

// The engine's pose of every instance equals the reference's, corner by corner (the engine's
// triangles index welded vertices, the reference's the file's): so welding kept positions and
// triangle order. Returns how many corners moved from `previous` (the reference's last pose).
std::size_t expect_same_pose(const AnimatedModel& model, const std::vector<reference::PosedInstance>& expected,
                             double ticks, const std::vector<reference::PosedInstance>* previous) {
    Pose pose;
    sample_clip(model, model.clips[0], ticks, pose);
    PoseScratch scratch;
    std::vector<Vec3> vertices;
    const double tolerance = 1e-9 * extent(expected);
    std::size_t moved = 0;
    EXPECT_EQ(model.instances.size(), expected.size());
    for (std::size_t i = 0; i < std::min(model.instances.size(), expected.size()); ++i) {
        const MeshInstance& instance = model.instances[i];
        const reference::PosedInstance& reference = expected[i];
        EXPECT_EQ(instance.name, reference.name);
        pose_instance(instance, pose, scratch, vertices);
        EXPECT_EQ(instance.triangles.size(), reference.triangles.size()) << instance.name;
        if (instance.triangles.size() != reference.triangles.size()) continue;
        std::size_t mismatches = 0;
        for (std::size_t t = 0; t < reference.triangles.size(); ++t) {
            for (int c = 0; c < 3; ++c) {
                const Vec3& got = vertices[instance.triangles[t][c]];
                const Vec3& want = reference.vertices[reference.triangles[t][c]];
                if ((got - want).cwiseAbs().maxCoeff() > tolerance && mismatches++ < 3) {
                    ADD_FAILURE() << instance.name << " at tick " << ticks << ", triangle " << t << " corner " << c
                                  << ": engine (" << got.transpose() << "), reference (" << want.transpose() << ")";
                }
                if (previous != nullptr &&
                    (*previous)[i].vertices[reference.triangles[t][c]] != want) {
                    ++moved;
                }
            }
        }
        EXPECT_EQ(mismatches, 0u) << instance.name << " at tick " << ticks;
    }
    return moved;
}

TEST_P(AnimatedTestModel, PoseEqualsTheReferenceBeforeBetweenAndAfterTheKeys) {
    REQUIRE_TESTMODEL(file, GetParam().file);
    const AnimatedModel model = read_animated_model(file);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file.string(), 0);
    ASSERT_NE(scene, nullptr);
    ASSERT_GE(model.clips.size(), 1u);
    EXPECT_EQ(model.instances.front().skinned(), GetParam().skinned);
    const double duration = model.clips[0].duration_ticks;
    // Before the first key, at it, between keys (fractions that fall between keys), at the
    // end, and after the last key.
    const double times[] = {-0.5 * duration - 1, 0, 0.137 * duration, 0.5 * duration + 0.01,
                            0.77 * duration, duration, 1.5 * duration + 2};
    std::vector<reference::PosedInstance> previous;
    std::size_t moved = 0;
    for (const double ticks : times) {
        SCOPED_TRACE("tick " + std::to_string(ticks));
        const std::vector<reference::PosedInstance> expected = reference::pose(*scene, 0, ticks);
        moved += expect_same_pose(model, expected, ticks, previous.empty() ? nullptr : &previous);
        previous = expected;
    }
    EXPECT_GT(moved, 0u) << "the clip moves nothing: the comparison would prove little";
}

INSTANTIATE_TEST_SUITE_P(
    AssimpTestModels, AnimatedTestModel,
    ::testing::Values(Case{"X/BCN_Epileptic.X", true}, Case{"FBX/animation_with_skeleton.fbx", true},
                      Case{"FBX/huesitos.fbx", true}, Case{"glTF2/simple_skin/simple_skin.gltf", true},
                      Case{"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", false},
                      Case{"X/Testwuson.X", true}, Case{"Collada/box_nested_animation.dae", true},
                      Case{"Collada/anims_with_full_rotations_between_keys.DAE", false}),
    [](const ::testing::TestParamInfo<Case>& param) {
        std::string name = std::filesystem::path(param.param.file).stem().string();
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    });

TEST(AnimatedModel, MorphCubeHasTwoTargetsAndAMorphChannel) {
    REQUIRE_TESTMODEL(file, "glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    const AnimatedModel model = read_animated_model(file);
    ASSERT_EQ(model.instances.size(), 1u);
    EXPECT_EQ(model.instances[0].morph_targets.size(), 2u);
    ASSERT_EQ(model.clips.size(), 1u);
    EXPECT_EQ(model.clips[0].morphs.size(), 1u);
    EXPECT_EQ(model.up_axis, 'y');  // glTF is Y-up
}

TEST(AnimatedModel, BoneNamingNoNodeIsAnErrorNamingFileMeshAndBone) {
    REQUIRE_TESTMODEL(file, "X/anim_test.x");
    try {
        read_animated_model(file);
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(file.string()), std::string::npos) << message;
        EXPECT_NE(message.find("names no node"), std::string::npos) << message;
        EXPECT_NE(message.find("bone"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(AnimatedModel, SkinnedVerticesWeldAcrossSeamsOnly) {
    REQUIRE_TESTMODEL(file, "FBX/animation_with_skeleton.fbx");
    const AnimatedModel model = read_animated_model(file);
    ASSERT_EQ(model.instances.size(), 1u);
    const MeshInstance& instance = model.instances[0];
    EXPECT_LT(instance.base.size(), 4224u);  // the file's 4,224 vertices are one per face corner
    // No two remaining vertices share a position and their influences.
    for (std::size_t a = 0; a < instance.base.size(); ++a) {
        for (std::size_t b = a + 1; b < instance.base.size(); ++b) {
            if (instance.base[a] != instance.base[b]) continue;
            const auto influences = [&](std::size_t v) {
                std::vector<std::pair<std::uint32_t, double>> list;
                for (std::uint32_t i = instance.influence_begin[v]; i < instance.influence_begin[v + 1]; ++i) {
                    list.emplace_back(instance.influence_bone[i], instance.influence_weight[i]);
                }
                return list;
            };
            EXPECT_NE(influences(a), influences(b)) << "vertices " << a << " and " << b << " should be one";
        }
    }
}

}  // namespace
}  // namespace collidescope
