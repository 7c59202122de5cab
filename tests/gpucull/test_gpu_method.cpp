// Mode 2 against the brute-force reference: the GPU cull may only remove pairs that do not
// collide. Seeded scenes built to break sampling (slivers, tiny triangles, touching at a point
// or an edge, coplanar contact, edge-on triangles) at very low resolutions, both cull variants,
// and the data sets at the small preset; plus that the cull does remove what it should.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>

namespace collidescope {
namespace {

using testing::make_frame;
using testing::reference_colliding_pairs;

PipelineConfig gpu_config(int resolution, GpuCullVariant variant, std::uint32_t per_query = 4, bool self = false) {
    PipelineConfig config;
    config.method = "gpu";
    config.self_collision = self;
    config.gpu.resolution = resolution;
    config.gpu.variant = variant;
    config.gpu.triangles_per_query = per_query;
    return config;
}

// Two triangle soups whose triangles touch the other's exactly: slivers, points, shared
// corners, edges lying in the other's plane.
std::vector<MeshData> touching_soups(std::mt19937_64& rng, std::uint32_t triangles) {
    MeshData a = testing::grid_soup(rng, triangles, 4, 0.25);
    MeshData b = testing::grid_soup(rng, triangles, 4, 0.25);
    std::uniform_real_distribution<double> tiny(0.0, 1e-7);
    for (std::size_t i = 0; i + 2 < b.vertices.size(); i += 9) {
        b.vertices[i + 1] = b.vertices[i] + Vec3(tiny(rng), 0, tiny(rng));  // a sliver
    }
    return {a, b};
}

class GpuAgainstBrute : public ::testing::TestWithParam<std::tuple<int, GpuCullVariant>> {};

TEST_P(GpuAgainstBrute, SeededSoupsAtLowResolution) {
    const auto [resolution, variant] = GetParam();
    constexpr std::uint64_t k_seed = 7001;
    std::cout << "[ seed     ] " << k_seed << " resolution " << resolution << '\n';
    Pipeline pipeline(gpu_config(resolution, variant));
    std::mt19937_64 rng(k_seed);
    std::uint64_t colliding = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Frame frame = make_frame(touching_soups(rng, 30));
        frame.index = static_cast<std::uint32_t>(trial);
        const std::vector<TrianglePair> expected = reference_colliding_pairs(frame, false);
        ASSERT_EQ(pipeline.process(frame).colliding_pairs, expected) << "seed " << k_seed << " trial " << trial;
        colliding += expected.size();
    }
    EXPECT_GT(colliding, 100u);  // the scenes do collide: the test exercises both outcomes
}

TEST_P(GpuAgainstBrute, RandomMultiObjectScenesWithSelfCollision) {
    const auto [resolution, variant] = GetParam();
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const Scene scene = testing::random_scene(seed, {4, 3, 30, 4});
        for (const bool self : {false, true}) {
            Pipeline pipeline(gpu_config(resolution, variant, 3, self));
            for (const Frame& frame : testing::all_frames(scene)) {
                ASSERT_EQ(pipeline.process(frame).colliding_pairs, reference_colliding_pairs(frame, self))
                    << "seed " << seed << " frame " << frame.index << " self " << self;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Resolutions, GpuAgainstBrute,
                         ::testing::Combine(::testing::Values(8, 16, 256),
                                            ::testing::Values(GpuCullVariant::Queries, GpuCullVariant::Flags)),
                         [](const auto& param_info) {
                             return std::to_string(std::get<0>(param_info.param)) +
                                    (std::get<1>(param_info.param) == GpuCullVariant::Queries ? "_queries" : "_flags");
                         });

// Two parallel sheets a gap apart whose boxes overlap (the lower one has a spike where the
// upper one is not): the view along their normal separates them, so the cull removes every
// triangle and the final step gets nothing.
TEST(GpuCull, SeparatedSheetsLeaveThePcs) {
    MeshData lower = testing::grid_sheet(8, 1.0);
    lower.vertices[0].z() = 0.5;  // the corner at x = y = 0, outside the upper sheet's x range
    const MeshData upper = testing::translated(testing::grid_sheet(8, 1.0), Vec3(0.5, 0, 0.01));
    const Frame frame = make_frame({lower, upper});
    for (const GpuCullVariant variant : {GpuCullVariant::Queries, GpuCullVariant::Flags}) {
        Pipeline pipeline(gpu_config(64, variant));
        const FrameResult result = pipeline.process(frame);
        ASSERT_TRUE(result.stats.gpu.has_value());
        EXPECT_EQ(result.stats.gpu->pcs_triangles_in, 256u);
        EXPECT_EQ(result.stats.gpu->pcs_triangles_out, 0u);
        EXPECT_EQ(result.stats.counts.candidate_pairs, 0u);
        EXPECT_TRUE(result.colliding_pairs.empty());
    }
}

// Touching sheets (the upper one's corner row lies in the lower one's plane) keep their pairs.
TEST(GpuCull, TouchingSheetsKeepTheirContacts) {
    const MeshData lower = testing::grid_sheet(8, 1.0);
    MeshData upper = testing::translated(testing::grid_sheet(8, 1.0), Vec3(0.5, 0, 0.01));
    for (std::size_t i = 0; i < upper.vertices.size(); i += 9) upper.vertices[i].z() = 0;  // x = 0.5 column
    const Frame frame = make_frame({lower, upper});
    const std::vector<TrianglePair> expected = reference_colliding_pairs(frame, false);
    ASSERT_FALSE(expected.empty());
    for (const int resolution : {8, 64, 512}) {
        Pipeline pipeline(gpu_config(resolution, GpuCullVariant::Queries));
        EXPECT_EQ(pipeline.process(frame).colliding_pairs, expected) << resolution;
    }
}

// Queries and flags read the same comparisons, so they leave the same PCS.
TEST(GpuCull, QueriesAndFlagsGiveTheSamePcs) {
    const Scene scene = make_builtin_scene("C:small");
    PipelineConfig queries_config = gpu_config(128, GpuCullVariant::Queries, 1);
    queries_config.gpu.adaptive_p = false;  // P stays 1
    queries_config.gpu.view_matrix = false;  // both use the views z, x, y
    PipelineConfig flags_config = gpu_config(128, GpuCullVariant::Flags);
    flags_config.gpu.view_matrix = false;
    Pipeline queries(queries_config);
    Pipeline flags(flags_config);
    for (std::uint32_t f = 0; f < scene.source->frame_count(); f += 5) {
        const Frame frame = scene.source->frame(f);
        const FrameResult a = queries.process(frame);
        const FrameResult b = flags.process(frame);
        EXPECT_EQ(a.stats.gpu->pcs_triangles_out, b.stats.gpu->pcs_triangles_out) << f;
        EXPECT_EQ(a.stats.counts.candidate_pairs, b.stats.counts.candidate_pairs) << f;
        EXPECT_EQ(a.colliding_pairs, b.colliding_pairs) << f;
    }
}

class GpuDataSets : public ::testing::TestWithParam<std::string> {};

TEST_P(GpuDataSets, SmallPresetMatchesBruteEveryFrame) {
    Scene scene;
    try {
        scene = make_builtin_scene(GetParam() + ":small");
    } catch (const UnavailableError& error) {
        FAIL() << error.what();  // scripts/setup.sh installs every data set
    }
    PipelineConfig brute_config;
    brute_config.self_collision = scene.self_collision;
    Pipeline brute(brute_config);
    Pipeline gpu(gpu_config(256, GpuCullVariant::Flags, 16, scene.self_collision));
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        ASSERT_EQ(gpu.process(frame).colliding_pairs, brute.process(frame).colliding_pairs)
            << GetParam() << " frame " << f;
    }
}

INSTANTIATE_TEST_SUITE_P(Small, GpuDataSets, ::testing::Values("A", "B", "C", "D", "E1", "E4", "demo"),
                         [](const auto& param_info) { return param_info.param; });

// The naive baseline and every mechanism switched off one at a time stay exact.
TEST(GpuCull, NaiveAndEveryMechanismSwitchStayExact) {
    const Scene scene = make_builtin_scene("D:small");
    std::vector<PipelineConfig> configs(5, gpu_config(64, GpuCullVariant::Queries, 2));
    configs[0].method = "gpu-naive";
    configs[1].gpu.view_matrix = false;
    configs[2].gpu.sort_objects = false;
    configs[3].gpu.adaptive_p = false;
    configs[4].gpu.object_level = false;
    Pipeline brute(PipelineConfig{});
    std::vector<std::unique_ptr<Pipeline>> pipelines;
    for (const PipelineConfig& config : configs) pipelines.push_back(std::make_unique<Pipeline>(config));
    for (std::uint32_t f = 0; f < scene.source->frame_count(); f += 3) {
        const Frame frame = scene.source->frame(f);
        const std::vector<TrianglePair> expected = brute.process(frame).colliding_pairs;
        for (std::size_t i = 0; i < pipelines.size(); ++i) {
            const FrameResult result = pipelines[i]->process(frame);
            ASSERT_EQ(result.colliding_pairs, expected) << "config " << i << " frame " << f;
            if (i == 0) {
                EXPECT_EQ(result.stats.method, "gpu-naive");
            }
            if (i == 0 && result.stats.gpu->triangles_per_query != 0) {
                EXPECT_EQ(result.stats.gpu->triangles_per_query, 1u);
            }
        }
    }
}

TEST(GpuCull, BadConfigurationIsRejected) {
    PipelineConfig config = gpu_config(0, GpuCullVariant::Queries);
    EXPECT_THROW(Pipeline{config}, std::invalid_argument);
    config = gpu_config(64, GpuCullVariant::Queries);
    config.gpu.views = {0, 3};
    EXPECT_THROW(Pipeline{config}, std::invalid_argument);
}

}  // namespace
}  // namespace collidescope
