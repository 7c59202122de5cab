// Algorithms 4 and 5, decision by decision, with scripted times and draws.

#include "decision/policy.hpp"

#include <gtest/gtest.h>

#include <deque>

namespace collidescope::decision {
namespace {

struct Script {
    std::deque<double> draws;
    Uniform uniform() {
        return [this] {
            EXPECT_FALSE(draws.empty()) << "the policy drew more often than scripted";
            if (draws.empty()) return 0.99;
            const double draw = draws.front();
            draws.pop_front();
            return draw;
        };
    }
};

AdaptiveOptions thesis_options() {
    AdaptiveOptions o;
    o.initial_exploration = 0.5;
    o.exploration_step = 0.1;
    o.max_exploration = 0.6;
    return o;
}

Outcome both(double aabb, double gpu) { return {aabb, gpu, k_unmeasured, aabb + gpu}; }
Outcome aabb_only(double aabb) { return {aabb, k_unmeasured, k_unmeasured, aabb}; }
Outcome gpu_only(double gpu) { return {k_unmeasured, gpu, k_unmeasured, gpu}; }

void expect(const Decision& d, Action action, std::uint8_t reason, std::uint8_t mode) {
    EXPECT_EQ(d.action, action);
    EXPECT_EQ(d.reason, reason) << decision_reason_name(d.reason);
    EXPECT_EQ(d.mode, mode);
}

TEST(ThesisPolicy, StartsBySamplingBoth) {
    Script script;
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    const Decision first = policy->decide({});
    expect(first, Action::SampleBoth, k_reason_initial_sample, 1);
    EXPECT_FALSE(first.start_rebuild);
    policy->observe(both(1.0, 5.0));
    EXPECT_DOUBLE_EQ(policy->inputs().aabb_ms, 1.0);
    EXPECT_DOUBLE_EQ(policy->inputs().gpu_ms, 5.0);
}

TEST(ThesisPolicy, Mode1KeepsAabbWhileFasterAndTheDrawMissesExploration) {
    Script script{{0.7, 0.9}};
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    policy->decide({});
    policy->observe(both(1.0, 5.0));
    const Decision d = policy->decide({});  // (4), draw 0.7 >= 0.5
    expect(d, Action::Aabb, k_reason_aabb_faster, 1);
    EXPECT_DOUBLE_EQ(d.draw, 0.7);
    policy->observe(aabb_only(2.0));
    expect(policy->decide({}), Action::Aabb, k_reason_aabb_faster, 1);
    EXPECT_TRUE(script.draws.empty());
}

TEST(ThesisPolicy, ExplorationDrawMovesToMode2ThenAabbFasterReturnsAndLowersExploration) {
    Script script{{0.2, 0.99}};
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    policy->decide({});
    policy->observe(both(1.0, 4.0));
    const Decision explore = policy->decide({});  // (8): 0.2 < 0.5
    expect(explore, Action::GpuImproved, k_reason_explore, 2);
    EXPECT_DOUBLE_EQ(explore.draw, 0.2);
    EXPECT_DOUBLE_EQ(policy->inputs().exploration, 0.6);  // inc_explore, capped at 0.6
    policy->observe(gpu_only(4.0));  // Alg. 5 (4): AABB_T 1 < GPU_T 4: back, exploration * 1/4
    EXPECT_DOUBLE_EQ(policy->inputs().exploration, 0.15);
    expect(policy->decide({}), Action::Aabb, k_reason_aabb_faster_again, 1);
    policy->observe(aabb_only(1.0));
}

TEST(ThesisPolicy, Mode2StaysWhileGpuFasterAndRaisesExplorationEachFrame) {
    Script script{{0.0}};
    AdaptiveOptions o = thesis_options();
    o.max_exploration = 1.0;
    auto policy = make_thesis_policy(o, script.uniform());
    policy->decide({});
    policy->observe(both(3.0, 4.0));
    expect(policy->decide({}), Action::GpuImproved, k_reason_explore, 2);  // exploration 0.6
    policy->observe(gpu_only(2.0));  // GPU now faster than AABB_T = 3: stay
    const Decision stay = policy->decide({});  // (2) inc_explore, (3) GPU 2
    expect(stay, Action::GpuImproved, k_reason_mode2, 2);
    EXPECT_DOUBLE_EQ(policy->inputs().exploration, 0.7);
    policy->observe(gpu_only(2.5));
    expect(policy->decide({}), Action::GpuImproved, k_reason_mode2, 2);
    EXPECT_DOUBLE_EQ(policy->inputs().exploration, 0.8);
}

TEST(ThesisPolicy, GpuFasterRebuildsInAThreadThenResamplesAndMovesToMode2) {
    Script script{{0.9}};
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    policy->decide({});
    policy->observe(both(6.0, 2.0));  // AABB slower
    const Decision rebuild = policy->decide({});  // (5)
    expect(rebuild, Action::GpuPlain, k_reason_rebuild_in_thread, 1);
    EXPECT_TRUE(rebuild.start_rebuild);
    policy->observe(gpu_only(2.0));
    FrameFacts running;
    running.rebuild_running = true;
    const Decision serving = policy->decide(running);  // GPU 1 serves while the thread builds
    expect(serving, Action::GpuPlain, k_reason_rebuild_in_thread, 1);
    EXPECT_FALSE(serving.start_rebuild);
    policy->observe(gpu_only(2.0));
    FrameFacts finished;
    finished.rebuild_finished = true;
    expect(policy->decide(finished), Action::SampleBoth, k_reason_resample, 1);
    policy->observe(both(3.0, 2.0));  // (6): GPU still faster: Mode 2
    expect(policy->decide({}), Action::GpuImproved, k_reason_gpu_still_faster, 2);
    policy->observe(gpu_only(2.0));
    expect(policy->decide({}), Action::GpuImproved, k_reason_mode2, 2);
}

TEST(ThesisPolicy, ResampleWithAabbFasterStaysInMode1) {
    Script script{{0.9}};
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    policy->decide({});
    policy->observe(both(6.0, 2.0));
    policy->decide({});
    policy->observe(gpu_only(2.0));
    policy->decide({});  // finished at once
    policy->observe(both(1.0, 2.0));
    expect(policy->decide({}), Action::Aabb, k_reason_aabb_faster, 1);
}

TEST(ThesisPolicy, RebuildAverageAboveGpuTimeMovesToMode2) {
    Script script;
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    policy->decide({});
    policy->observe(both(1.0, 3.0));
    FrameFacts facts;
    facts.rebuild_average_ms = 5.0;  // (7): 5 > GPU_T 3
    const Decision d = policy->decide(facts);
    expect(d, Action::GpuImproved, k_reason_rebuild_too_slow, 2);
    EXPECT_TRUE(std::isnan(d.draw));
    EXPECT_DOUBLE_EQ(policy->inputs().rebuild_avg_ms, 5.0);
}

TEST(ThesisPolicy, WithoutGpuOnlyAabb) {
    Script script;
    auto policy = make_thesis_policy(thesis_options(), script.uniform());
    FrameFacts facts;
    facts.gpu_available = false;
    for (int i = 0; i < 3; ++i) {
        expect(policy->decide(facts), Action::Aabb, k_reason_aabb_faster, 1);
        policy->observe(aabb_only(1.0));
    }
}

}  // namespace
}  // namespace collidescope::decision
