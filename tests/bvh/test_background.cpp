// The background rebuild (thesis contribution 3): frames stay exact while a worker rebuilds,
// trees are swapped in and refit, and the method's counts are thread-independent when the
// swap point is deterministic. The Background* tests are a ThreadSanitizer target
// (docs/how-to/sanitizers.md).

#include "bvh/bvh_helpers.hpp"

#include "support/scene_builders.hpp"

#include "bvh/background_rebuild.hpp"

#include "collidescope/datasets.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstdio>
#include <random>

namespace collidescope::bvh {
namespace {

// The slowest exploding dragons (24 frames): the trees degrade as the triangles fly apart,
// and the quality rule with a low limit rebuilds often.
std::vector<Frame> exploding_frames() {
    return testing::all_frames(make_builtin_scene("E4:small"));
}

AabbConfig config_with(BackgroundMode mode, testing::TreeChecker& checker) {
    AabbConfig config;
    config.background = mode;
    config.policy.quality_limit = 1.02;
    config.policy.payback_frames = 0;  // the SAH cost alone: rebuilds whatever they cost
    config.on_tree = checker.hook();
    return config;
}

TEST(BackgroundRebuild, NextFrameSwapsRefitsAndStaysExact) {
    const std::vector<Frame> frames = exploding_frames();
    testing::TreeChecker checker;
    const std::unique_ptr<Method> method = make_aabb_method(config_with(BackgroundMode::NextFrame, checker));
    const testing::MethodRun run = testing::run_method(*method, frames, true);
    const testing::MethodRun brute = testing::run_pipeline("brute", frames, true, 0);
    EXPECT_EQ(run.pairs, brute.pairs);
    std::uint64_t started = 0;
    std::uint64_t swapped = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        started += run.stats[f].aabb->background_started;
        swapped += run.stats[f].aabb->background_swaps;
        // A batch started at frame f is swapped in at frame f + 1.
        if (f > 0) {
            EXPECT_EQ(run.stats[f].aabb->background_swaps, run.stats[f - 1].aabb->background_started) << f;
        }
    }
    EXPECT_GT(started, 0u);
    EXPECT_GT(swapped, 0u);
    EXPECT_EQ(checker.swaps, swapped);
    EXPECT_EQ(checker.failures, std::vector<std::string>{});
}

TEST(BackgroundRebuild, AsyncStaysExactOnEveryFrame) {
    const std::vector<Frame> frames = exploding_frames();
    const testing::MethodRun brute = testing::run_pipeline("brute", frames, true, 0);
    std::uint64_t started = 0;
    for (int repeat = 0; repeat < 3; ++repeat) {
        testing::TreeChecker checker;
        const std::unique_ptr<Method> method = make_aabb_method(config_with(BackgroundMode::Async, checker));
        const testing::MethodRun run = testing::run_method(*method, frames, true);
        EXPECT_EQ(run.pairs, brute.pairs);
        for (const FrameStats& stats : run.stats) started += stats.aabb->background_started;
        EXPECT_EQ(checker.failures, std::vector<std::string>{});
    }
    EXPECT_GT(started, 0u);
}

// A tree degraded far past the limit is rebuilt in the frame, not handed to the worker:
// data set D jumps from its first frame (a flying soup) to frame 49, where the refit tree's
// SAH cost is many times its built cost and traversing it would cost far more than a build.
TEST(BackgroundRebuild, FarDegradedTreeIsRebuiltInTheFrame) {
    const Scene scene = make_builtin_scene("D");
    const std::vector<Frame> frames = {scene.source->frame(0), scene.source->frame(49)};
    const testing::MethodRun brute = testing::run_pipeline("brute", frames, true, 0);
    for (const double in_frame_quality : {4.0, 1e9}) {
        testing::TreeChecker checker;
        AabbConfig config = config_with(BackgroundMode::Async, checker);
        config.policy.quality_limit = 1.5;
        config.policy.in_frame_quality = in_frame_quality;
        const std::unique_ptr<Method> method = make_aabb_method(config);
        const testing::MethodRun run = testing::run_method(*method, frames, true);
        EXPECT_EQ(run.pairs, brute.pairs) << in_frame_quality;
        const AabbFrameInfo& jump = *run.stats[1].aabb;
        std::printf("D, frame 0 to frame 49: refit tree quality %.2f\n", jump.tree_quality);
        ASSERT_GT(jump.tree_quality, 4.0) << "D no longer degrades from frame 0 to frame 49";
        if (in_frame_quality == 4.0) {
            EXPECT_GT(jump.rebuilt_objects, 0u);
            EXPECT_EQ(jump.background_started, 0u);
        } else {  // the limit out of reach: the old behaviour, the worker gets it
            EXPECT_EQ(jump.rebuilt_objects, 0u);
            EXPECT_GT(jump.background_started, 0u);
        }
        EXPECT_EQ(checker.failures, std::vector<std::string>{});
    }
}

TEST(BackgroundRebuild, DestroyedWhileAWorkerRuns) {
    std::mt19937_64 rng(1);
    const MeshData mesh = testing::grid_soup(rng, 50000, 100);
    auto topology = std::make_shared<Topology>();
    topology->triangles = mesh.triangles;
    topology->vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
    {
        BackgroundRebuild background;
        background.start({{0, topology, mesh.vertices, 0, RebuildReason::Quality}});
        EXPECT_TRUE(background.busy());
    }  // the destructor waits for the worker
    BackgroundRebuild background;
    EXPECT_FALSE(background.take(false).has_value());
    background.start({{3, topology, mesh.vertices, 7, RebuildReason::Quality}});
    std::optional<std::vector<RebuiltTree>> done = background.take(true);
    ASSERT_TRUE(done.has_value());
    ASSERT_EQ(done->size(), 1u);
    EXPECT_EQ((*done)[0].job.object, 3u);
    EXPECT_TRUE(validate((*done)[0].tree, mesh.triangles, mesh.vertices).empty());
    EXPECT_FALSE(background.busy());
}

// The ThreadSanitizer target (docs/how-to/sanitizers.md): the engine thread hands snapshots to the
// rebuild worker (std::future) while TBB runs each thread's loops. With one TBB thread the
// only hand-off is ours; with two, TBB's workers run the refits, traversals and the worker's
// builds too, which the TSan build makes visible through its TBB bridge (tests/sanitize/).
TEST(BackgroundRebuild, ThreadSanitizerHandOff) {
    const std::vector<Frame> frames = testing::all_frames(make_builtin_scene("E1:small"));
    const testing::MethodRun brute = testing::run_pipeline("brute", frames, true, 1);
    for (const std::size_t threads : {1u, 2u}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        std::uint64_t started = 0;
        std::uint64_t swapped = 0;
        for (const BackgroundMode mode : {BackgroundMode::NextFrame, BackgroundMode::Async, BackgroundMode::Async}) {
            testing::TreeChecker checker;
            const std::unique_ptr<Method> method = make_aabb_method(config_with(mode, checker));
            const testing::MethodRun run = testing::run_method(*method, frames, true);
            EXPECT_EQ(run.pairs, brute.pairs) << threads << " threads";
            for (const FrameStats& stats : run.stats) {
                started += stats.aabb->background_started;
                swapped += stats.aabb->background_swaps;
            }
            EXPECT_EQ(checker.failures, std::vector<std::string>{}) << threads << " threads";
        }
        EXPECT_GT(started, 0u) << threads << " threads";
        EXPECT_GT(swapped, 0u) << threads << " threads";  // NextFrame always swaps what it started
    }
}

TEST(AabbDeterminism, SameCountsForEveryThreadCount) {
    const std::vector<Frame> frames = testing::all_frames(testing::random_scene(11, {6, 3, 300, 12}));
    std::vector<testing::MethodRun> runs;
    for (const int threads : {1, 2, 4}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        testing::TreeChecker checker;
        const std::unique_ptr<Method> method = make_aabb_method(config_with(BackgroundMode::NextFrame, checker));
        runs.push_back(testing::run_method(*method, frames, true));
    }
    for (std::size_t k = 1; k < runs.size(); ++k) {
        EXPECT_EQ(runs[k].pairs, runs[0].pairs);
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const FrameCounts& a = runs[k].stats[f].counts;
            const FrameCounts& b = runs[0].stats[f].counts;
            EXPECT_EQ(a.box_tests, b.box_tests);
            EXPECT_EQ(a.nodes_visited, b.nodes_visited);
            EXPECT_EQ(a.candidate_pairs, b.candidate_pairs);
            EXPECT_EQ(a.colliding_pairs, b.colliding_pairs);
            EXPECT_EQ(a.rebuilds, b.rebuilds);
            EXPECT_EQ(a.self_culled_triangles, b.self_culled_triangles);
            EXPECT_EQ(runs[k].stats[f].aabb->tree_quality, runs[0].stats[f].aabb->tree_quality);
        }
    }
}

TEST(BackgroundRebuild, AutoUsesTheWorkerOnlyWhenAHardwareThreadIsFree) {
    const int hardware = tbb::info::default_concurrency();
    std::printf("TBB default concurrency here: %d\n", hardware);
    EXPECT_FALSE(rebuild_in_background(AabbBackground::Auto, 0));  // 0 = all hardware threads
    EXPECT_FALSE(rebuild_in_background(AabbBackground::Auto, hardware));
    EXPECT_FALSE(rebuild_in_background(AabbBackground::Auto, hardware + 4));
    EXPECT_EQ(rebuild_in_background(AabbBackground::Auto, 1), hardware > 1);
    EXPECT_EQ(rebuild_in_background(AabbBackground::Auto, hardware - 1), hardware > 1);
    for (int threads : {0, 1, hardware, hardware + 4}) {
        EXPECT_TRUE(rebuild_in_background(AabbBackground::On, threads));
        EXPECT_FALSE(rebuild_in_background(AabbBackground::Off, threads));
    }
    AabbOptions options;
    EXPECT_EQ(options.background, AabbBackground::Auto);
    EXPECT_EQ(aabb_config(options, 0).background, BackgroundMode::Off);
    options.background = AabbBackground::On;
    EXPECT_EQ(aabb_config(options, 0).background, BackgroundMode::Async);
}

}  // namespace
}  // namespace collidescope::bvh
