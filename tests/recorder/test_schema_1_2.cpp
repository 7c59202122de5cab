// Schema 1.2: the decision system's and the hybrid framework's per-frame values, the GPU cull's
// passes, survivors and depth images, written by the Recorder and read back through the
// Recording's accessors; files of schema 1.1 (no such groups) still open and read as empty.

#include "recording_helpers.hpp"

#include "mesh/temp_files.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/recorder.hpp"
#include "collidescope/recorder/schema.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

namespace collidescope {
namespace {

using testing_files::TempDir;

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

// Distinct, frame-dependent values for every field, so a swapped column or row shows.
DecisionInfo decision_of(std::uint32_t f) {
    DecisionInfo d;
    d.policy = static_cast<std::uint8_t>(f % 2);
    d.mode = static_cast<std::uint8_t>(1 + f % 2);
    d.action = static_cast<std::uint8_t>(f % 5);
    d.reason = static_cast<std::uint8_t>(f % 11);
    d.switched = f % 3 == 0;
    d.rebuilding = f % 4 == 0;
    d.aabb_ms = 1.25 + f;
    d.gpu_ms = 2.5 + f;
    d.hybrid_ms = f == 2 ? k_nan : 3.75 + f;  // NaN is a value too (not measured yet)
    d.rebuild_avg_ms = 0.125 * f;
    d.exploration = 0.01 * f;
    d.draw = 0.5 + 0.03125 * f;
    return d;
}

HybridFrameInfo hybrid_of(std::uint32_t f) {
    HybridFrameInfo h;
    h.a1 = 100 + f;
    h.a2 = 50 + f;
    h.tri_1 = 40 + f;
    h.tri_r = 30 + f;
    h.tri_2 = 20 + f;
    h.a_i_ms = 1e-5 * (f + 1);
    h.t_i_ms = 2e-5 * (f + 1);
    h.o_ms = 3e-3 * (f + 1);
    h.unculled = 0.5;
    h.pure_aabb_ms = 0.7 + f;
    h.hybrid_ms = 0.9 + f;
    h.tri_1_needed = 123.5;
    h.predicted_hybrid_wins = f % 2 == 1;
    return h;
}

GpuFrameInfo gpu_of(std::uint32_t f) {
    GpuFrameInfo g;
    g.pcs_objects_in = 2;
    g.pcs_triangles_in = 100 + f;
    g.pcs_triangles_out = 10 + f;
    g.chosen_views = {2, 0};
    for (std::uint8_t p = 0; p < 1 + f % 3; ++p) {
        g.passes.push_back({1, static_cast<std::uint8_t>(p % 3), static_cast<std::uint8_t>(p % 2), 90u + p, 7u + f, 12u + p,
                            std::uint64_t{1} << (33 + p), 16u + f});
    }
    for (std::uint32_t t = 0; t < 3 + f; ++t) g.survivors.push_back({t % 2, 5 * t + f});
    if (f % 2 == 0) {
        for (std::uint8_t view : {std::uint8_t{2}, std::uint8_t{0}}) {
            GpuDepthImage image;
            image.level = 1;
            image.view = view;
            image.width = 8 + view;
            image.height = 4;
            image.depth_near = -1.5 - f;
            image.depth_far = 2.25 + f;
            for (std::uint32_t p = 0; p < image.width * image.height; ++p) {
                image.depth.push_back(p % 3 == 0 ? 1.0f : static_cast<float>(p) / static_cast<float>(image.width * image.height));
            }
            g.depth_images.push_back(std::move(image));
        }
    }
    return g;
}

FrameStats stats_of(std::uint32_t f) {
    FrameStats stats;
    stats.frame = f;
    stats.method = "brute";
    if (f % 2 == 0) stats.decision = decision_of(f);
    if (f % 3 != 1) stats.hybrid = hybrid_of(f);
    if (f != 3) stats.gpu = gpu_of(f);
    return stats;
}

constexpr std::uint32_t k_synthetic_frames = 6;

// Feeds the recorder frames whose stats carry every 1.2 detail (on some frames only).
void record_synthetic(const std::filesystem::path& file) {
    const Scene scene = testing::crossing_sheets(2, k_synthetic_frames);
    recorder::SessionInfo session;
    session.scene = scene.name;
    session.method = "brute";
    session.frame_end = k_synthetic_frames;
    session.object_names = {"flat", "upright"};
    recorder::RecorderConfig config;
    config.path = file;
    recorder::Recorder rec(config, session, scene.source->frame(0));
    for (std::uint32_t f = 0; f < k_synthetic_frames; ++f) {
        const Frame frame = scene.source->frame(f);
        const FrameStats stats = stats_of(f);
        rec.on_frame({frame, stats, {}});
    }
    rec.finish();
}

// The visitor's (name, value, unit) for `info`, or NaNs with the same names when absent.
template <class Info, class ForEach>
void expect_values(const std::vector<recorder::Series<double>>& series, std::size_t row, const std::optional<Info>& info,
                   ForEach for_each) {
    std::size_t i = 0;
    for_each(info.value_or(Info{}), [&](const char* name, double value, const char* unit) {
        ASSERT_LT(i, series.size());
        EXPECT_EQ(series[i].name, name);
        EXPECT_EQ(series[i].unit, unit);
        const double got = series[i].values.at(row);
        if (!info || std::isnan(value)) {
            EXPECT_TRUE(std::isnan(got)) << name << " row " << row << ": " << got;
        } else {
            EXPECT_EQ(got, value) << name << " row " << row;
        }
        ++i;
    });
    EXPECT_EQ(i, series.size());
}

void expect_passes_equal(const std::vector<GpuPassInfo>& got, const std::vector<GpuPassInfo>& expected, std::size_t row) {
    ASSERT_EQ(got.size(), expected.size()) << "row " << row;
    for (std::size_t p = 0; p < got.size(); ++p) {
        std::vector<std::uint64_t> a, b;
        for_each_pass_field(got[p], [&](const char*, std::uint64_t v) { a.push_back(v); });
        for_each_pass_field(expected[p], [&](const char*, std::uint64_t v) { b.push_back(v); });
        EXPECT_EQ(a, b) << "row " << row << " pass " << p;
    }
}

void expect_depth_equal(const std::vector<GpuDepthImage>& got, const std::vector<GpuDepthImage>& expected, std::size_t row) {
    ASSERT_EQ(got.size(), expected.size()) << "row " << row;
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].level, expected[i].level);
        EXPECT_EQ(got[i].view, expected[i].view);
        EXPECT_EQ(got[i].width, expected[i].width);
        EXPECT_EQ(got[i].height, expected[i].height);
        EXPECT_EQ(got[i].depth_near, expected[i].depth_near);
        EXPECT_EQ(got[i].depth_far, expected[i].depth_far);
        ASSERT_EQ(got[i].depth.size(), expected[i].depth.size());
        for (std::size_t p = 0; p < got[i].depth.size(); ++p) {
            if (expected[i].depth[p] == 1.0f) {
                EXPECT_EQ(got[i].depth[p], 1.0f) << "row " << row << " image " << i << " pixel " << p;
            } else {  // quantised to 1/65535; drawn pixels stay below 1
                EXPECT_NEAR(got[i].depth[p], expected[i].depth[p], 0.5 / 65535 + 1e-7) << "row " << row << " pixel " << p;
                EXPECT_LT(got[i].depth[p], 1.0f);
            }
        }
    }
}

TEST(Schema12, DecisionHybridPassesSurvivorsAndDepthComeBack) {
    TempDir dir;
    const auto file = dir.path() / "run.h5";
    record_synthetic(file);
    const recorder::Recording rec(file);
    EXPECT_EQ(rec.version_major(), 1);
    EXPECT_EQ(rec.version_minor(), recorder::schema::k_version_minor);
    ASSERT_EQ(rec.frames_complete(), k_synthetic_frames);
    const auto decision = rec.frame_values("decision");
    const auto hybrid = rec.frame_values("hybrid");
    const auto gpu = rec.frame_values("gpu");
    ASSERT_FALSE(decision.empty());
    ASSERT_FALSE(hybrid.empty());
    EXPECT_TRUE(rec.frame_values("no_such_group").empty());
    for (std::uint32_t f = 0; f < k_synthetic_frames; ++f) {
        const FrameStats stats = stats_of(f);
        expect_values(decision, f, stats.decision, [](const auto& i, auto&& v) { for_each_decision_value(i, v); });
        expect_values(hybrid, f, stats.hybrid, [](const auto& i, auto&& v) { for_each_hybrid_value(i, v); });
        expect_values(gpu, f, stats.gpu, [](const auto& i, auto&& v) { for_each_gpu_value(i, v); });
        const GpuFrameInfo g = stats.gpu.value_or(GpuFrameInfo{});
        expect_passes_equal(rec.gpu_passes(f), g.passes, f);
        EXPECT_EQ(rec.survivors(f), g.survivors) << "row " << f;
        expect_depth_equal(rec.depth_images(f), g.depth_images, f);
    }
    EXPECT_THROW(rec.survivors(k_synthetic_frames), InputError);
    EXPECT_THROW(rec.depth_images(k_synthetic_frames), InputError);
}

TEST(Schema12, ASchema11FileReadsTheNewGroupsAsEmpty) {
    TempDir dir;
    const auto file = dir.path() / "run.h5";
    record_synthetic(file);
    // What a 1.1 writer left: no decision, hybrid, survivors or depth datasets.
    namespace schema = recorder::schema;
    for (const char* path : {schema::k_frame_decision, schema::k_frame_hybrid, schema::k_gpu_survivors,
                             schema::k_gpu_survivor_offsets, schema::k_gpu_depth}) {
        testing::delete_link(file, path);
    }
    testing::set_int_attr(file, "/", recorder::schema::k_attr_version_minor, 1);
    const recorder::Recording rec(file);
    EXPECT_EQ(rec.version_minor(), 1);
    ASSERT_EQ(rec.frames_complete(), k_synthetic_frames);
    EXPECT_TRUE(rec.frame_values("decision").empty());
    EXPECT_TRUE(rec.frame_values("hybrid").empty());
    EXPECT_FALSE(rec.frame_values("gpu").empty());
    for (std::uint32_t f = 0; f < k_synthetic_frames; ++f) {
        EXPECT_TRUE(rec.survivors(f).empty());
        EXPECT_TRUE(rec.depth_images(f).empty());
        expect_passes_equal(rec.gpu_passes(f), stats_of(f).gpu.value_or(GpuFrameInfo{}).passes, f);
    }
}

// The real GPU cull: what its reports held comes back, depth images on frames 0, 2, 4 only.
TEST(Schema12, GpuMethodRecordingMatchesItsReports) {
    TempDir dir;
    const auto file = dir.path() / "run.h5";
    const Scene scene = make_builtin_scene("C:small");
    PipelineConfig config;
    config.method = "gpu";
    config.threads = 2;
    config.gpu.resolution = 64;
    config.gpu.depth_every = 2;
    const auto frames = testing::record_in_process(scene, file, 0, 6, config);
    const recorder::Recording rec(file);
    ASSERT_EQ(rec.frames_complete(), frames.size());
    const auto gpu = rec.frame_values("gpu");
    std::size_t images = 0;
    for (std::size_t r = 0; r < frames.size(); ++r) {
        const FrameStats& stats = frames[r].stats;
        ASSERT_TRUE(stats.gpu.has_value());
        expect_values(gpu, r, stats.gpu, [](const auto& i, auto&& v) { for_each_gpu_value(i, v); });
        expect_passes_equal(rec.gpu_passes(r), stats.gpu->passes, r);
        EXPECT_EQ(rec.survivors(r), stats.gpu->survivors) << "row " << r;
        expect_depth_equal(rec.depth_images(r), stats.gpu->depth_images, r);
        if (stats.frame % 2 != 0) {
            EXPECT_TRUE(stats.gpu->depth_images.empty()) << "frame " << stats.frame;
        }
        images += stats.gpu->depth_images.size();
    }
    EXPECT_GT(images, 0u);
    EXPECT_TRUE(std::isnan(rec.frame_values("decision").at(0).values[0])) << "no decision system: NaN";
}

}  // namespace
}  // namespace collidescope
