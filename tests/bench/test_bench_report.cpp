// bench's summary arithmetic on hand-made frames: the oracle-best ratio of the adaptive
// methods, their mode shares and switches, and the hybrid analysis's prediction count.

#include "bench_report.hpp"

#include "collidescope/stats.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace collidescope {
namespace {

app::BenchFrame frame(const std::string& method, std::uint32_t index, double total_ms, std::uint8_t mode = 0,
                      std::uint8_t action = 255) {
    app::BenchFrame f;
    f.method = method;
    f.frame = index;
    f.ms.assign(11, 0.0);
    f.ms.back() = total_ms;
    for_each_count(FrameCounts{}, [&](const char*, std::uint64_t) { f.counts.push_back(0); });
    f.mode = mode;
    f.action = action;
    return f;
}

TEST(BenchReport, OracleIsTheSumOfPerFrameMinimaOfTheFixedMethods) {
    app::BenchScene scene;
    scene.name = "X";
    scene.preset = "small";
    scene.methods = {"aabb", "gpu", "adaptive-cost"};
    scene.frames = {frame("aabb", 0, 1.0), frame("aabb", 1, 5.0), frame("aabb", 2, 1.0),
                    frame("gpu", 0, 3.0), frame("gpu", 1, 2.0), frame("gpu", 2, 4.0),
                    frame("adaptive-cost", 0, 1.0, 1, k_action_aabb), frame("adaptive-cost", 1, 2.5, 2, k_action_gpu_improved),
                    frame("adaptive-cost", 2, 1.5, 1, k_action_hybrid)};
    const std::vector<app::BenchSummary> rows = app::summarize({scene});
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].oracle_ratio, 0.0);  // fixed methods get none
    EXPECT_DOUBLE_EQ(rows[2].total_ms, 5.0);
    EXPECT_DOUBLE_EQ(rows[2].oracle_ratio, 5.0 / (1.0 + 2.0 + 1.0));
    EXPECT_EQ(rows[2].mode2_frames, 1u);
    EXPECT_EQ(rows[2].hybrid_frames, 1u);
    EXPECT_EQ(rows[2].switches, 2u);
}

TEST(BenchReport, HybridAnalysisCountsCorrectPredictions) {
    std::vector<std::string> names;
    for_each_hybrid_value(HybridFrameInfo{}, [&](const char* name, double, const char*) { names.emplace_back(name); });
    const auto values = [&](bool predicts_hybrid) {
        HybridFrameInfo info;
        info.predicted_hybrid_wins = predicts_hybrid;
        info.tri_1 = 10;
        std::vector<double> v;
        for_each_hybrid_value(info, [&](const char*, double value, const char*) { v.push_back(value); });
        return v;
    };
    app::BenchScene scene;
    scene.name = "Y";
    scene.preset = "small";
    scene.methods = {"aabb", "hybrid"};
    scene.frames = {frame("aabb", 0, 2.0), frame("aabb", 1, 2.0), frame("aabb", 2, 2.0),
                    frame("hybrid", 0, 1.0), frame("hybrid", 1, 3.0), frame("hybrid", 2, 3.0)};
    scene.frames[3].hybrid = values(true);   // right: hybrid won
    scene.frames[4].hybrid = values(true);   // wrong
    scene.frames[5].hybrid = values(false);  // right
    const std::string text = app::hybrid_analysis({scene});
    EXPECT_NE(text.find("on 2 of 3 frames (predicted hybrid 2, hybrid won 1)"), std::string::npos) << text;
    EXPECT_NE(text.find("TRI_1 10"), std::string::npos) << text;
}

}  // namespace
}  // namespace collidescope

namespace collidescope {
namespace {

// bench/scripts/bench_oracle.py on a hand-made frames.csv: both oracles, for the adaptive rows only.
TEST(BenchOracleScript, ComputesBothOracles) {
    const std::filesystem::path csv = std::filesystem::temp_directory_path() / "collidescope_bench_oracle_frames.csv";
    {
        std::ofstream out(csv);
        out << "scene,preset,method,frame,ms_total\n"
               "X,small,aabb,0,1.0\nX,small,aabb,1,5.0\n"
               "X,small,aabb-thesis,0,0.5\nX,small,aabb-thesis,1,6.0\n"
               "X,small,gpu,0,3.0\nX,small,gpu,1,2.0\n"
               "X,small,adaptive-cost,0,1.0\nX,small,adaptive-cost,1,2.0\n";
    }
    const std::string command = "/usr/bin/python3 '" COLLIDESCOPE_SOURCE_DIR "/bench/scripts/bench_oracle.py' '" + csv.string() + "'";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
    ASSERT_EQ(pclose(pipe), 0) << output;
    std::filesystem::remove(csv);
    // all fixed: 0.5 + 2 = 2.5; candidates (aabb, gpu): 1 + 2 = 3; adaptive: 3.
    EXPECT_NE(output.find("X:small,adaptive-cost,3.000,1.200,1.000"), std::string::npos) << output;
    EXPECT_NE(output.find("X:small,aabb,6.000,,"), std::string::npos) << output;
}

}  // namespace
}  // namespace collidescope
