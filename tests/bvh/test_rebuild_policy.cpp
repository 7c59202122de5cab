// The rebuild policy on scripted timings, alone and through the method with an injected
// clock.

#include "bvh/bvh_helpers.hpp"

#include "support/scene_builders.hpp"

#include "bvh/rebuild_policy.hpp"

#include <gtest/gtest.h>

namespace collidescope::bvh {
namespace {

TEST(RebuildPolicy, NewTreesAndTopologyChangesAlwaysBuild) {
    for (const RebuildRule rule : {RebuildRule::Quality, RebuildRule::Thesis, RebuildRule::Never}) {
        const RebuildPolicy policy({rule});
        EXPECT_EQ(policy.decide({false, false}), RebuildReason::Initial);
        EXPECT_EQ(policy.decide({false, true}), RebuildReason::Initial);
        EXPECT_EQ(policy.decide({true, true, 1.0, 0.0, 100.0}), RebuildReason::Topology);
        EXPECT_EQ(policy.decide({true, false, 1.0, 0.0, 100.0}), RebuildReason::None);
    }
}

TEST(RebuildPolicy, ThesisRuleAtThreeQuartersOfARebuild) {
    const RebuildPolicy policy({RebuildRule::Thesis});
    // A scripted run: rebuild costs 8 ms; detection times creep up frame by frame.
    const double rebuild_ms = 8.0;
    const std::vector<std::pair<double, RebuildReason>> script = {
        {1.0, RebuildReason::None}, {5.9, RebuildReason::None}, {6.0, RebuildReason::None},  // 6 = 3/4 * 8: not above
        {6.01, RebuildReason::Thesis}, {20.0, RebuildReason::Thesis}, {0.0, RebuildReason::None}};
    for (const auto& [detection_ms, expected] : script) {
        // Quality plays no part in this rule.
        EXPECT_EQ(policy.decide({true, false, 100.0, detection_ms, rebuild_ms}), expected) << detection_ms;
    }
    const RebuildPolicy half({RebuildRule::Thesis, 0.5});
    EXPECT_EQ(half.decide({true, false, 1.0, 4.5, 8.0}), RebuildReason::Thesis);
}

TEST(RebuildPolicy, QualityRuleAtTheLimit) {
    const RebuildPolicy policy({RebuildRule::Quality, 0.75, 1.5, 0});  // the SAH cost alone
    EXPECT_EQ(policy.decide({true, false, 1.0, 1000.0, 1.0}), RebuildReason::None);  // timings play no part
    EXPECT_EQ(policy.decide({true, false, 1.5, 0.0, 1.0}), RebuildReason::None);
    EXPECT_EQ(policy.decide({true, false, 1.5001, 0.0, 1.0}), RebuildReason::Quality);
    const RebuildPolicy never({RebuildRule::Never});
    EXPECT_EQ(never.decide({true, false, 1e9, 1e9, 0.0}), RebuildReason::None);
}

// Past the limit, a rebuild is chosen when what it can save within payback_frames frames,
// traversal_ms * (1 - 1 / quality) a frame, reaches its cost; past in_frame_quality always.
// Inputs: {has_tree, topology_changed, quality, detection_ms, rebuild_ms, traversal_ms}.
TEST(RebuildPolicy, QualityRuleRebuildsWhenTheRebuildPaysWithinThePaybackFrames) {
    const RebuildPolicy policy({RebuildRule::Quality, 0.75, 1.5, 10, 4});
    // quality 2: half the traversal time saved a frame; 10 frames of 2 ms save 10 ms.
    EXPECT_EQ(policy.decide({true, false, 2.0, 2.0, 10.0, 2.0}), RebuildReason::Quality);
    EXPECT_EQ(policy.decide({true, false, 2.0, 2.0, 10.01, 2.0}), RebuildReason::None);
    // The narrow phase does not count: the same candidates are tested whatever the tree.
    EXPECT_EQ(policy.decide({true, false, 2.0, 100.0, 10.0, 1.0}), RebuildReason::None);
    EXPECT_EQ(policy.decide({true, false, 2.0, 0.5, 150.0, 0.5}), RebuildReason::None);  // a big build, little to save
    EXPECT_EQ(policy.decide({true, false, 1.4, 1e6, 1.0, 1e6}), RebuildReason::None);    // under the limit: never
    // Past in_frame_quality the tree is rebuilt whatever the times.
    EXPECT_EQ(policy.decide({true, false, 4.5, 0.0, 150.0, 0.0}), RebuildReason::Quality);
    // Initial and topology rebuilds do not weigh costs.
    EXPECT_EQ(policy.decide({false, false, 1.0, 0.0, 150.0}), RebuildReason::Initial);
    EXPECT_EQ(policy.decide({true, true, 1.0, 0.0, 150.0}), RebuildReason::Topology);
}

TEST(RebuildPolicy, ReasonNames) {
    EXPECT_EQ(rebuild_reason_name(RebuildReason::Thesis), "thesis");
    EXPECT_EQ(rebuild_reason_names(k_rebuild_topology | k_rebuild_quality), "topology,quality");
    EXPECT_EQ(rebuild_reason_names(0), "");
    // The stats bits and the policy's reasons are the same values.
    EXPECT_EQ(static_cast<int>(RebuildReason::Initial), k_rebuild_initial);
    EXPECT_EQ(static_cast<int>(RebuildReason::Topology), k_rebuild_topology);
    EXPECT_EQ(static_cast<int>(RebuildReason::Thesis), k_rebuild_thesis);
    EXPECT_EQ(static_cast<int>(RebuildReason::Quality), k_rebuild_quality);
}

// Through the method: a clock that advances `tick` ms per reading makes every measured
// detection time 2 * tick (two readings span traversal and narrow phase), far above or far
// below 3/4 of the real (sub-millisecond to few-ms) build time of a small scene.
std::vector<FrameStats> run_with_clock(double tick) {
    const Scene scene = testing::random_scene(5, {4, 6, 60, 8});
    double time = 0;
    AabbConfig config;
    config.policy.rule = RebuildRule::Thesis;
    config.background = BackgroundMode::Off;
    config.clock_ms = [&time, tick] { return time += tick; };
    const std::unique_ptr<Method> method = make_aabb_method(config);
    return testing::run_method(*method, testing::all_frames(scene), false).stats;
}

TEST(RebuildPolicy, ThesisRuleThroughTheMethodWithAScriptedClock) {
    const std::vector<FrameStats> slow = run_with_clock(1000.0);
    const std::vector<FrameStats> frozen = run_with_clock(0.0);
    ASSERT_EQ(slow.size(), 6u);
    EXPECT_EQ(slow[0].aabb->rebuild_reasons, k_rebuild_initial);
    for (std::size_t f = 1; f < slow.size(); ++f) {
        // (An object that starts touching another gets its first tree: "initial" may join.)
        EXPECT_NE(slow[f].aabb->rebuild_reasons & k_rebuild_thesis, 0) << "frame " << f;
        EXPECT_GT(slow[f].aabb->rebuilt_objects, 0u);
        EXPECT_EQ(slow[f].ms.traversal, 1000.0);  // stage times come from the injected clock
        EXPECT_EQ(frozen[f].aabb->rebuild_reasons & k_rebuild_thesis, 0) << "frame " << f;
    }
}

}  // namespace
}  // namespace collidescope::bvh
