// Data sets A-E: documented sizes, determinism, float32 coordinates, topology phases, errors.

#include "scene_helpers.hpp"

#include "collidescope/error.hpp"
#include "datasets/generators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace collidescope::testing {
namespace {

using datasets::k_dataset_sizes;
using datasets::preset_name;

constexpr std::uint64_t k_seed = 1;

std::uint64_t triangle_count(const Frame& frame) {
    std::uint64_t count = 0;
    for (const ObjectFrame& object : frame.objects) count += object.triangle_count();
    return count;
}

// Hash of every frame, asked for in order.
std::uint64_t hash_scene(Scene& scene) {
    std::uint64_t hash = 0xCBF29CE484222325ULL;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        hash = hash_frame(scene.source->frame(f), hash);
    }
    return hash;
}

class SceneTest : public ::testing::TestWithParam<std::string> {
protected:
    // The scene at `preset`; nullopt (and why, in m_unavailable) when its mesh package is missing,
    // which fails the test: scripts/setup.sh installs every data set.
    std::optional<Scene> make(std::string_view preset, std::uint64_t seed = k_seed) {
        std::string why;
        std::optional<Scene> scene = try_make_scene(GetParam(), preset, seed, why);
        if (!scene) m_unavailable = why;
        return scene;
    }
    std::string m_unavailable;
};

TEST_P(SceneTest, SizesMatchTheDocumentedTable) {
    for (const datasets::DatasetSize& size : k_dataset_sizes) {
        if (size.scene != GetParam()) continue;
        SCOPED_TRACE(preset_name(size.preset));
        std::optional<Scene> scene = make(preset_name(size.preset));
        ASSERT_TRUE(scene) << m_unavailable;
        EXPECT_EQ(scene->name, GetParam());
        EXPECT_EQ(scene->preset, preset_name(size.preset));
        ASSERT_EQ(scene->source->frame_count(), size.frames);
        // Soups keep the triangle count: first, middle and last frame agree with the table.
        for (const std::uint32_t f : {0u, size.frames / 2, size.frames - 1}) {
            EXPECT_EQ(triangle_count(scene->source->frame(f)), size.triangles) << "frame " << f;
        }
    }
}

TEST_P(SceneTest, SameSeedGivesBitIdenticalFrames) {
    std::optional<Scene> first = make("small");
    ASSERT_TRUE(first) << m_unavailable;
    std::optional<Scene> second = make("small");
    ASSERT_TRUE(second);
    EXPECT_EQ(hash_scene(*first), hash_scene(*second));
}

TEST_P(SceneTest, FramesDoNotDependOnRequestOrder) {
    std::optional<Scene> scene = make("small");
    ASSERT_TRUE(scene) << m_unavailable;
    const std::uint32_t last = scene->source->frame_count() - 1;
    const std::uint64_t last_first = hash_frame(scene->source->frame(last));
    const std::uint64_t zero = hash_frame(scene->source->frame(0));
    EXPECT_EQ(hash_frame(scene->source->frame(last)), last_first);
    EXPECT_EQ(hash_frame(scene->source->frame(0)), zero);
}

TEST_P(SceneTest, OtherSeedGivesOtherFrames) {
    std::optional<Scene> first = make("small", 1);
    ASSERT_TRUE(first) << m_unavailable;
    std::optional<Scene> second = make("small", 2);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->seed, 2u);
    EXPECT_NE(hash_scene(*first), hash_scene(*second));
}

TEST_P(SceneTest, VerticesAreFiniteFloat32AndIndicesValid) {
    std::optional<Scene> scene = make("small");
    ASSERT_TRUE(scene) << m_unavailable;
    for (std::uint32_t f = 0; f < scene->source->frame_count(); ++f) {
        const Frame frame = scene->source->frame(f);
        ASSERT_EQ(frame.index, f);
        ASSERT_EQ(frame.objects.size(), 2u);
        for (const ObjectFrame& object : frame.objects) {
            ASSERT_EQ(object.vertices.size(), object.topology->vertex_count) << "frame " << f;
            for (const Vec3& v : object.vertices) {
                for (int k = 0; k < 3; ++k) {
                    ASSERT_TRUE(std::isfinite(v[k])) << "frame " << f;
                    ASSERT_TRUE(is_float32(v[k])) << "frame " << f << ": " << v[k];
                }
            }
            for (const TriIndices& tri : object.topology->triangles) {
                for (const std::uint32_t corner : tri) {
                    ASSERT_LT(corner, object.topology->vertex_count);
                }
            }
        }
    }
}

// The frames where some object's topology revision differs from the previous frame's.
std::vector<std::uint32_t> topology_changes(Scene& scene) {
    std::vector<std::uint32_t> changes;
    std::vector<std::uint64_t> previous;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        std::vector<std::uint64_t> revisions;
        for (const ObjectFrame& object : frame.objects) {
            revisions.push_back(object.topology->revision);
        }
        if (f > 0 && revisions != previous) changes.push_back(f);
        previous = revisions;
    }
    return changes;
}

TEST_P(SceneTest, TopologyChangesOnlyWhereTheDataSetSaysSo) {
    std::optional<Scene> scene = make("small");
    ASSERT_TRUE(scene) << m_unavailable;
    const std::string& name = GetParam();
    const std::uint32_t frames = scene->source->frame_count();
    std::vector<std::uint32_t> expected;                // A, B, C: fixed topology
    if (name == "D") expected = {frames / 2};           // soup -> tori at the middle frame
    if (name[0] == 'E') expected = {1};                 // intact -> soup when the blast starts
    EXPECT_EQ(topology_changes(*scene), expected);
}

TEST_P(SceneTest, RevisionsAreUniqueAcrossScenes) {
    std::optional<Scene> first = make("small");
    ASSERT_TRUE(first) << m_unavailable;
    std::optional<Scene> second = make("small");
    ASSERT_TRUE(second);
    std::set<std::uint64_t> revisions;
    std::size_t topologies = 0;
    for (Scene* scene : {&*first, &*second}) {
        for (const std::uint32_t f : {0u, scene->source->frame_count() - 1}) {
            for (const ObjectFrame& object : scene->source->frame(f).objects) {
                revisions.insert(object.topology->revision);
                ++topologies;
            }
        }
    }
    // Two scenes x two objects, and a second topology per object where it changes.
    const std::size_t per_scene = GetParam() == "D" || GetParam()[0] == 'E' ? 4 : 2;
    EXPECT_EQ(revisions.size(), 2 * per_scene);
    EXPECT_EQ(topologies, 8u);
}

TEST_P(SceneTest, UnknownPresetIsAnInputError) {
    std::string why;
    EXPECT_THROW(try_make_scene(GetParam(), "huge", k_seed, why), InputError);
}

INSTANTIATE_TEST_SUITE_P(DataSets, SceneTest, ::testing::ValuesIn(dataset_names()),
                         [](const auto& param_info) { return param_info.param; });

TEST(SceneE, SpeedOutsideOneToFourIsAnInputError) {
    EXPECT_THROW(datasets::make_scene_E(0, "small", k_seed), InputError);
    EXPECT_THROW(datasets::make_scene_E(5, "small", k_seed), InputError);
}

TEST(Presets, EmptyMeansDefault) {
    EXPECT_EQ(datasets::parse_preset("", "B"), datasets::Preset::Default);
    const Scene scene = datasets::make_scene_B("", k_seed);
    EXPECT_EQ(scene.preset, "default");
}

TEST(Presets, TableCoversEveryScenePresetOnce) {
    std::set<std::pair<std::string_view, datasets::Preset>> seen;
    for (const datasets::DatasetSize& size : k_dataset_sizes) {
        seen.insert({size.scene, size.preset});
    }
    EXPECT_EQ(seen.size(), dataset_names().size() * 3);
    EXPECT_EQ(seen.size(), k_dataset_sizes.size());
}

}  // namespace
}  // namespace collidescope::testing
