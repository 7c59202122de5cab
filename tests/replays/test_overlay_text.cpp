// The overlay's text (replays/src/overlay_text.hpp): a value a frame did not measure reads "not
// run" (or its line is left out), never "nan"; measured values print as before.

#include "overlay_text.hpp"

#include "collidescope/stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace collidescope::replays {
namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

bool has_nan(const std::string& text) { return text.find("nan") != std::string::npos || text.find("inf") != std::string::npos; }

// An adaptive frame that ran AABB alone: the policy never timed the GPU or the hybrid, drew
// nothing, and has no rebuild average yet.
FrameData aabb_frame_of_adaptive() {
    FrameData frame;
    frame.method = "adaptive";
    frame.decision = {{"policy", 1},        {"mode", 1},          {"action", k_action_aabb}, {"reason", k_reason_aabb_faster},
                      {"switched", 0},      {"rebuilding", 0},    {"aabb_ms", 1.25},         {"gpu_ms", k_nan},
                      {"hybrid_ms", k_nan}, {"rebuild_avg_ms", k_nan}, {"exploration", 0.03},   {"draw", k_nan}};
    frame.aabb = {{"rebuild_reasons", 0}, {"rebuilt_objects", 0}, {"background_started", 0}, {"background_swaps", 0}, {"tree_quality", 1.1}};
    frame.hybrid = {{"tri_1", k_nan}, {"tri_r", k_nan}, {"tri_2", k_nan}};
    frame.gpu = {{"queries", k_nan}, {"triangles_per_query", k_nan}, {"query_ms", k_nan}};
    return frame;
}

TEST(OverlayText, UnmeasuredValuesSayNotRunInsteadOfNan) {
    const FrameData frame = aabb_frame_of_adaptive();
    const std::vector<std::string> lines = decision_text(frame);
    ASSERT_EQ(lines.size(), 4u);
    for (const std::string& line : lines) EXPECT_FALSE(has_nan(line)) << line;
    EXPECT_EQ(lines[1], "AABB_T 1.25 ms  GPU_T not run  hybrid not run");
    EXPECT_EQ(lines[2], "rebuild average none yet  (cost policy)");
    EXPECT_EQ(lines[3], "exploration 0.030  draw none");
    EXPECT_FALSE(has_nan(gpu_queries_text(frame))) << gpu_queries_text(frame);
    EXPECT_EQ(gpu_queries_text(frame), "queries -   P - tris/query   O not measured");
}

TEST(OverlayText, LinesOfGroupsTheFrameDidNotRunAreLeftOut) {
    FrameData frame = aabb_frame_of_adaptive();
    EXPECT_FALSE(hybrid_text(frame).has_value());
    ASSERT_TRUE(aabb_text(frame).has_value());
    EXPECT_EQ(*aabb_text(frame), "AABB: rebuilt 0 (no rebuild), tree quality 1.10");
    for (auto& [name, value] : frame.aabb) value = k_nan;  // a GPU frame of an adaptive recording
    EXPECT_FALSE(aabb_text(frame).has_value());
    frame.decision.clear();
    EXPECT_EQ(decision_text(frame), std::vector<std::string>{"not recorded (method adaptive; record --method adaptive)"});
}

TEST(OverlayText, MeasuredValuesPrintAsMeasured) {
    FrameData frame = aabb_frame_of_adaptive();
    for (auto& [name, value] : frame.decision) {
        if (std::isnan(value)) value = 2.5;
    }
    frame.hybrid = {{"tri_1", 10}, {"tri_r", 20}, {"tri_2", 3}};
    frame.gpu = {{"queries", 12}, {"triangles_per_query", 16}, {"query_ms", 0.0123}};
    EXPECT_EQ(decision_text(frame)[1], "AABB_T 1.25 ms  GPU_T 2.5 ms  hybrid 2.5 ms");
    EXPECT_EQ(decision_text(frame)[3], "exploration 0.030  draw 2.500");
    EXPECT_EQ(*hybrid_text(frame), "hybrid: TRI_1 10  TRI_R 20  TRI_2 3");
    EXPECT_EQ(gpu_queries_text(frame), "queries 12   P 16 tris/query   O 0.0123 ms");
    EXPECT_EQ(measured("%.3g ms", std::numeric_limits<double>::infinity()), "not run");
}

}  // namespace
}  // namespace collidescope::replays
