// The cost policy, decision by decision: the cheapest estimate runs, the others are probed
// when the budget allows, the GPU estimate follows the PCS size, rebuilds start in a thread.

#include "decision/policy.hpp"

#include <gtest/gtest.h>

namespace collidescope::decision {
namespace {

AdaptiveOptions options(double budget = 0.1) {
    AdaptiveOptions o;
    o.probe_budget = budget;
    o.smoothing = 1.0;  // estimates = the last measurement: easy to script
    return o;
}

FrameFacts facts(std::uint64_t triangles) {
    FrameFacts f;
    f.pcs_triangles = triangles;
    return f;
}

Outcome ran(Action action, double ms) {
    Outcome o;
    o.frame_ms = ms;
    if (action == Action::Aabb) o.aabb_ms = ms;
    if (action == Action::GpuImproved) o.gpu_ms = ms;
    if (action == Action::Hybrid) o.hybrid_ms = ms;
    return o;
}

TEST(CostPolicy, FirstFrameMeasuresAabb) {
    auto policy = make_cost_policy(options(), GpuCostPrior{1.0, 0.001});
    const Decision d = policy->decide(facts(1000));
    EXPECT_EQ(d.action, Action::Aabb);
    EXPECT_EQ(d.reason, k_reason_cost_probe);
}

TEST(CostPolicy, RunsTheCheapestAndProbesOthersOnlyWhenTheBudgetAllows) {
    // GPU prior: 1 + 0.001 * 1000 = 2 ms; hybrid before its first run: AABB + 1 ms.
    AdaptiveOptions o = options(0.1);
    o.use_hybrid = false;
    auto policy = make_cost_policy(o, GpuCostPrior{1.0, 0.001});
    policy->decide(facts(1000));
    policy->observe(ran(Action::Aabb, 1.0));  // AABB 1 ms, GPU predicted 2 ms: extra 1 ms
    // The probe of the GPU is allowed once 0.1 x elapsed >= 1 ms: after 10 ms of frames.
    int frames = 1;  // 1 ms elapsed so far
    Decision d;
    for (;;) {
        d = policy->decide(facts(1000));
        if (d.action != Action::Aabb) break;
        EXPECT_EQ(d.reason, k_reason_cost_cheapest);
        policy->observe(ran(Action::Aabb, 1.0));
        ++frames;
        ASSERT_LT(frames, 100);
    }
    EXPECT_EQ(frames, 10);
    EXPECT_EQ(d.action, Action::GpuImproved);
    EXPECT_EQ(d.reason, k_reason_cost_probe);
    EXPECT_EQ(d.mode, 2);
    EXPECT_DOUBLE_EQ(policy->inputs().gpu_ms, 2.0);
}

TEST(CostPolicy, GpuEstimateScalesWithThePcsAndSwitchesWhenCheaper) {
    AdaptiveOptions o = options(1.0);
    o.use_hybrid = false;
    auto policy = make_cost_policy(o, GpuCostPrior{1.0, 0.001});
    policy->decide(facts(1000));
    policy->observe(ran(Action::Aabb, 3.0));
    const Decision d = policy->decide(facts(1000));  // GPU predicted 2 < 3: cheapest
    EXPECT_EQ(d.action, Action::GpuImproved);
    EXPECT_EQ(d.reason, k_reason_cost_cheapest);
    EXPECT_TRUE(d.start_rebuild);  // AABB is not the cheapest: rebuild its trees in a thread
    policy->observe(ran(Action::GpuImproved, 4.0));  // measured 4 where 2 was predicted: scale 2
    policy->decide(facts(500));
    EXPECT_DOUBLE_EQ(policy->inputs().gpu_ms, 2.0 * (1.0 + 0.5));
}

TEST(CostPolicy, AFinishedRebuildIsMeasuredAtOnce) {
    AdaptiveOptions o = options(0.0);  // no probing by budget
    o.use_hybrid = false;
    auto policy = make_cost_policy(o, GpuCostPrior{0.0, 0.001});
    policy->decide(facts(1000));
    policy->observe(ran(Action::Aabb, 5.0));
    Decision d = policy->decide(facts(1000));
    ASSERT_EQ(d.action, Action::GpuImproved);
    ASSERT_TRUE(d.start_rebuild);
    policy->observe(ran(Action::GpuImproved, 1.0));
    FrameFacts running = facts(1000);
    running.rebuild_running = true;
    d = policy->decide(running);
    EXPECT_EQ(d.action, Action::GpuImproved);
    EXPECT_FALSE(d.start_rebuild);
    policy->observe(ran(Action::GpuImproved, 1.0));
    FrameFacts finished = facts(1000);
    finished.rebuild_finished = true;
    d = policy->decide(finished);
    EXPECT_EQ(d.action, Action::Aabb);
    EXPECT_EQ(d.reason, k_reason_cost_probe);
    policy->observe(ran(Action::Aabb, 0.5));  // the rebuilt trees are fast: AABB wins again
    d = policy->decide(facts(1000));
    EXPECT_EQ(d.action, Action::Aabb);
    EXPECT_EQ(d.reason, k_reason_cost_cheapest);
}

TEST(CostPolicy, HybridIsProbedAndKeptWhenItWins) {
    auto policy = make_cost_policy(options(0.5), GpuCostPrior{10.0, 0.01});  // the GPU alone is hopeless
    policy->decide(facts(1000));
    policy->observe(ran(Action::Aabb, 4.0));  // hybrid predicted 4 + 10: extra 10 ms
    Decision d;
    int frames = 0;
    do {
        d = policy->decide(facts(1000));
        policy->observe(ran(d.action, d.action == Action::Hybrid ? 1.0 : 4.0));
        ASSERT_LT(++frames, 100);
    } while (d.action != Action::Hybrid);
    EXPECT_EQ(d.reason, k_reason_cost_probe);
    d = policy->decide(facts(1000));
    EXPECT_EQ(d.action, Action::Hybrid);
    EXPECT_EQ(d.reason, k_reason_cost_cheapest);
    EXPECT_EQ(d.mode, 1);
}

TEST(CostPolicy, WithoutGpuOnlyAabb) {
    auto policy = make_cost_policy(options(1.0), GpuCostPrior{0.0, 0.0});
    FrameFacts f = facts(1000);
    f.gpu_available = false;
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(policy->decide(f).action, Action::Aabb);
        policy->observe(ran(Action::Aabb, 10.0));
    }
}

}  // namespace
}  // namespace collidescope::decision

namespace collidescope::decision {
namespace {

TEST(CostPolicy, WithoutAPriorTheGpuStaysOutAndThePriorIsAskedForOnceAffordable) {
    AdaptiveOptions o = options(0.5);
    o.use_hybrid = false;
    o.calibration_ms = 10;  // asked for once 0.5 x elapsed >= 10 ms: after 20 ms of frames
    auto policy = make_cost_policy(o, std::nullopt);
    int frames = 0;
    Decision d;
    for (;;) {  // AABB at 3 ms; a GPU at 2 ms would win, but nobody knows
        d = policy->decide(facts(1000));
        EXPECT_EQ(d.action, Action::Aabb);
        policy->observe(ran(Action::Aabb, 3.0));
        if (d.calibrate) break;
        ASSERT_LT(++frames, 100);
    }
    EXPECT_EQ(frames, 7);  // 7 frames x 3 ms = 21 ms >= 20 ms
    EXPECT_TRUE(std::isnan(policy->inputs().gpu_ms));
    EXPECT_FALSE(policy->decide(facts(1000)).calibrate);  // asked once only
    policy->observe(ran(Action::Aabb, 3.0));
    policy->set_gpu_prior({1.0, 0.001});
    EXPECT_EQ(policy->decide(facts(1000)).action, Action::GpuImproved);
}

}  // namespace
}  // namespace collidescope::decision
