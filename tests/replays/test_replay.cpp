// The replayer end to end: the built `collidescope record` makes small recordings, the built
// `collidescope replay` renders them, and the PNGs are decoded and checked pixel by pixel.

#include "replay_helpers.hpp"

#include "support/cli_runner.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/replays/camera.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <unistd.h>
#include <set>

namespace collidescope {
namespace {

using testing::count_pixels;
using testing::Image;
using testing::read_png;
using testing::run_cli;

// demo:small: a torus and a waving sheet; frames 0-2 apart, the middle ones collide.
constexpr const char* k_scene = "demo:small";

// The first recorded row with pairs and one without.
struct KnownRows {
    std::uint64_t colliding = UINT64_MAX;
    std::uint64_t apart = UINT64_MAX;
};

KnownRows known_rows(const recorder::Recording& recording) {
    KnownRows rows;
    const std::vector<std::uint64_t> pairs = recording.pair_counts();
    for (std::uint64_t row = 0; row < pairs.size(); ++row) {
        if (pairs[row] > 0 && rows.colliding == UINT64_MAX) rows.colliding = row;
        if (pairs[row] == 0 && rows.apart == UINT64_MAX) rows.apart = row;
    }
    return rows;
}

std::string frame_name(std::uint32_t frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.png", frame);
    return name;
}

// A fixed camera above and in front of the frame's bounds, as a --camera argument.
std::pair<replays::CameraSpec, std::string> fixed_camera(const recorder::Recording& recording, std::uint64_t row) {
    replays::Bounds bounds;
    for (std::uint32_t object = 0; object < recording.objects().size(); ++object) {
        const std::vector<float> xyz = recording.positions(object, row);
        for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) bounds.add(xyz[i], xyz[i + 1], xyz[i + 2]);
    }
    replays::CameraSpec spec;
    spec.kind = replays::CameraSpec::Kind::Fixed;
    spec.target_given = true;
    double radius = 0;
    for (int i = 0; i < 3; ++i) {
        spec.target[i] = 0.5 * (bounds.min[i] + bounds.max[i]);
        radius = std::max(radius, bounds.max[i] - bounds.min[i]);
    }
    const std::array<double, 3> direction = {0.3, -0.6, 1.0};
    for (int i = 0; i < 3; ++i) spec.eye[i] = spec.target[i] + direction[i] * radius * 1.4;
    char text[256];
    std::snprintf(text, sizeof text, "fixed:%.9g,%.9g,%.9g:%.9g,%.9g,%.9g", spec.eye[0], spec.eye[1], spec.eye[2],
                  spec.target[0], spec.target[1], spec.target[2]);
    return {spec, text};
}

// The depth colour map's hues (viridis: green above red), not grey text.
bool viridis_like(const std::uint8_t* p) { return p[1] > 60 && p[1] > p[0] + 20; }

class Replay : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        // One recording per process: ctest runs each test as its own process, several at once.
        s_dir = testing::test_dir("suite_" + std::to_string(::getpid()));
        testing::record(k_scene, "gpu", s_dir / "gpu.h5");
    }
    static void TearDownTestSuite() { std::filesystem::remove_all(s_dir); }
    static std::filesystem::path s_dir;
};
std::filesystem::path Replay::s_dir;

TEST_F(Replay, WritesOneDecodablePngPerFrameOfTheRequestedSize) {
    const std::filesystem::path out = testing::test_dir("sizes");
    const testing::CliResult result =
        run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", (out / "frames").string(), "--size", "320x200", "--frames", "2:6"},
                out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    for (std::uint32_t frame = 2; frame < 6; ++frame) {
        const Image image = read_png(out / "frames" / frame_name(frame));
        ASSERT_EQ(image.width, 320) << frame;
        EXPECT_EQ(image.height, 200) << frame;
    }
    EXPECT_FALSE(std::filesystem::exists(out / "frames" / frame_name(1)));
    EXPECT_FALSE(std::filesystem::exists(out / "frames" / frame_name(6)));
    EXPECT_NE(result.out.find("wrote 4 frames to"), std::string::npos) << result.out;
}

TEST_F(Replay, CollidingTrianglesCarryTheCollisionColourAndApartFramesDoNot) {
    const recorder::Recording recording(s_dir / "gpu.h5");
    const KnownRows rows = known_rows(recording);
    ASSERT_NE(rows.colliding, UINT64_MAX);
    ASSERT_NE(rows.apart, UINT64_MAX);
    const std::uint32_t frame = recording.frame_indices()[rows.colliding];
    const std::uint32_t apart = recording.frame_indices()[rows.apart];
    const auto [spec, camera_arg] = fixed_camera(recording, rows.colliding);
    const std::filesystem::path out = testing::test_dir("colours");
    for (const std::uint32_t f : {frame, apart}) {
        const testing::CliResult result = run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", out.string(), "--size",
                                                   "400x300", "--frames", std::to_string(f), "--camera", camera_arg,
                                                   "--show", "meshes,collisions"},
                                                  out);
        ASSERT_EQ(result.exit_code, 0) << result.err;
    }
    const Image image = read_png(out / frame_name(frame));
    ASSERT_EQ(image.width, 400);
    const replays::Camera camera = replays::make_camera(spec, {}, {0, 0, 400, 300}, 0, 1);
    // Every triangle of the frame in world coordinates, and which collide.
    struct Triangle {
        std::array<std::array<double, 3>, 3> corners;
        bool colliding = false;
    };
    std::set<std::pair<std::uint32_t, std::uint32_t>> colliding;
    for (const TrianglePair& pair : recording.pairs(rows.colliding)) {
        colliding.insert({pair.obj_a, pair.tri_a});
        colliding.insert({pair.obj_b, pair.tri_b});
    }
    std::vector<Triangle> triangles;
    for (std::uint32_t object = 0; object < recording.objects().size(); ++object) {
        const std::vector<float> xyz = recording.positions(object, rows.colliding);
        const std::vector<TriIndices> indices = recording.triangles(object, recording.topology_at(object, frame));
        for (std::uint32_t t = 0; t < indices.size(); ++t) {
            Triangle triangle;
            for (int k = 0; k < 3; ++k) {
                for (int i = 0; i < 3; ++i) triangle.corners[k][i] = xyz[3 * indices[t][k] + i];
            }
            triangle.colliding = colliding.count({object, t}) != 0;
            triangles.push_back(triangle);
        }
    }
    // What the eye sees through a triangle's centre: the nearest triangle along that ray
    // (Moller-Trumbore), so occlusion is known exactly.
    auto nearest_along = [&](const std::array<double, 3>& to) {
        std::array<double, 3> d{};
        for (int i = 0; i < 3; ++i) d[i] = to[i] - spec.eye[i];
        double best = 2.0;
        const Triangle* hit = nullptr;
        for (const Triangle& t : triangles) {
            std::array<double, 3> e1{}, e2{}, s{};
            for (int i = 0; i < 3; ++i) {
                e1[i] = t.corners[1][i] - t.corners[0][i];
                e2[i] = t.corners[2][i] - t.corners[0][i];
                s[i] = spec.eye[i] - t.corners[0][i];
            }
            const std::array<double, 3> p = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
            const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
            if (std::abs(det) < 1e-15) continue;
            const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
            const std::array<double, 3> q = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
            const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
            const double along = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
            if (u < 0 || v < 0 || u + v > 1 || along <= 0 || along >= best) continue;
            best = along;
            hit = &t;
        }
        return hit;
    };
    auto red_near = [&](const std::array<double, 3>& p) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = int(p[0]) + dx;
                const int y = int(p[1]) + dy;
                if (x >= 0 && y >= 0 && x < image.width && y < image.height && testing::is_collision_colour(image.at(x, y))) {
                    return true;
                }
            }
        }
        return false;
    };
    // At every triangle's centre, the pixel is red exactly when the nearest triangle there collides.
    std::size_t seen_colliding = 0, seen_colliding_red = 0, seen_other = 0, seen_other_red = 0;
    for (const Triangle& t : triangles) {
        std::array<double, 3> c{};
        for (int k = 0; k < 3; ++k) {
            for (int i = 0; i < 3; ++i) c[i] += t.corners[k][i] / 3.0;
        }
        const std::array<double, 3> p = camera.project(c[0], c[1], c[2]);
        if (p[0] < 1 || p[1] < 1 || p[0] >= 399 || p[1] >= 299) continue;
        const Triangle* front = nearest_along(c);
        if (front == nullptr) continue;
        if (front->colliding) {
            ++seen_colliding;
            seen_colliding_red += red_near(p) ? 1 : 0;
        } else {
            ++seen_other;
            seen_other_red += testing::is_collision_colour(image.at(int(p[0]), int(p[1]))) ? 1 : 0;
        }
    }
    EXPECT_GT(seen_colliding, 10u);
    EXPECT_GT(seen_other, 50u);
    EXPECT_GE(double(seen_colliding_red), 0.95 * double(seen_colliding)) << seen_colliding_red << " of " << seen_colliding;
    // a centre that sees a non-colliding triangle may lie within a pixel of a colliding one's edge
    EXPECT_LE(double(seen_other_red), 0.03 * double(seen_other)) << seen_other_red << " of " << seen_other;
    // A frame without pairs has meshes but not one collision-coloured pixel.
    const Image apart_image = read_png(out / frame_name(apart));
    const replays::Rect all = {0, 0, 400, 300};
    EXPECT_GT(count_pixels(apart_image, all, [](const std::uint8_t* p) { return !testing::is_background(p); }), 2000u);
    EXPECT_EQ(count_pixels(apart_image, all, testing::is_collision_colour), 0u);
}

TEST_F(Replay, OverlayLegendAndTimelineRegionsHoldTextAndBars) {
    const std::filesystem::path out = testing::test_dir("overlay");
    for (const char* show : {"all", "meshes"}) {
        const testing::CliResult result = run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", (out / show).string(),
                                                   "--size", "800x450", "--frames", "10", "--show", show},
                                                  out);
        ASSERT_EQ(result.exit_code, 0) << result.err;
    }
    const Image with = read_png(out / "all" / frame_name(10));
    const Image without = read_png(out / "meshes" / frame_name(10));
    ASSERT_EQ(with.width, 800);
    ASSERT_EQ(without.width, 800);
    const replays::FrameLayout layout = replays::frame_layout(800, 450, replays::k_layer_all);
    for (const auto& [name, rect] : {std::pair{"panel", layout.panel}, std::pair{"legend", layout.legend},
                                     std::pair{"depth", layout.depth}, std::pair{"timeline", layout.timeline}}) {
        const std::uint64_t area = std::uint64_t(rect.w) * std::uint64_t(rect.h);
        ASSERT_GT(area, 0u) << name;
        EXPECT_GT(count_pixels(with, rect, testing::is_bright), area / 200) << name;
    }
    EXPECT_EQ(count_pixels(without, layout.panel, testing::is_bright), 0u);
    // The timeline's bars carry the mode colour (Mode 2, the GPU cull: orange).
    EXPECT_GT(count_pixels(with, layout.timeline, [](const std::uint8_t* p) { return p[0] > 200 && p[1] > 120 && p[1] < 190 && p[2] < 80; }),
              100u);
}

TEST_F(Replay, SameRecordingAndOptionsGiveTheSameBytesWhateverTheThreads) {
    const std::filesystem::path out = testing::test_dir("determinism");
    for (const char* threads : {"1", "2", "3"}) {
        const testing::CliResult result =
            run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", (out / threads).string(), "--size", "480x270",
                     "--threads", threads, "--frames", "0:8", "--camera", "orbit", "--contact-sheet",
                     (out / threads).string() + "/sheet.png"},
                    out);
        ASSERT_EQ(result.exit_code, 0) << result.err;
    }
    for (std::uint32_t frame = 0; frame < 8; ++frame) {
        const std::string one = testing::read_bytes(out / "1" / frame_name(frame));
        ASSERT_FALSE(one.empty());
        EXPECT_EQ(one, testing::read_bytes(out / "2" / frame_name(frame))) << frame;
        EXPECT_EQ(one, testing::read_bytes(out / "3" / frame_name(frame))) << frame;
    }
    EXPECT_EQ(testing::read_bytes(out / "1" / "sheet.png"), testing::read_bytes(out / "3" / "sheet.png"));
    // Orbiting: the first and the last frame differ in where the meshes are.
    EXPECT_NE(testing::read_bytes(out / "1" / frame_name(0)), testing::read_bytes(out / "1" / frame_name(7)));
}

// --gl egl renders through EGL (the GPU path on a machine with one). Under Mesa both backends
// run llvmpipe, so the images must be the very bytes OSMesa gives.
TEST_F(Replay, EglGivesTheOsmesaImagesUnderTheSameRenderer) {
    const std::filesystem::path out = testing::test_dir("gl_backends");
    std::map<std::string, std::string> rate_lines;
    for (const char* gl : {"osmesa", "egl"}) {
        const testing::CliResult result =
            run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", (out / gl).string(), "--size", "320x200",
                     "--frames", "0:4", "--gl", gl, "--contact-sheet", (out / gl).string() + "/sheet.png"},
                    out);
        ASSERT_EQ(result.exit_code, 0) << result.err;
        rate_lines[gl] = result.err;
    }
    EXPECT_NE(rate_lines["osmesa"].find("via OSMesa"), std::string::npos) << rate_lines["osmesa"];
    EXPECT_NE(rate_lines["egl"].find("via EGL"), std::string::npos) << rate_lines["egl"];
    const bool same_renderer = rate_lines["egl"].find("llvmpipe") != std::string::npos;
    for (std::uint32_t frame = 0; frame < 4; ++frame) {
        const Image image = read_png(out / "egl" / frame_name(frame));
        EXPECT_EQ(image.width, 320) << frame;
        if (same_renderer) {
            EXPECT_EQ(testing::read_bytes(out / "egl" / frame_name(frame)),
                      testing::read_bytes(out / "osmesa" / frame_name(frame))) << frame;
        }
    }
    if (same_renderer) {
        EXPECT_EQ(testing::read_bytes(out / "egl" / "sheet.png"), testing::read_bytes(out / "osmesa" / "sheet.png"));
    }
}

TEST_F(Replay, ContactSheetShowsTheSelectedFrames) {
    const std::filesystem::path out = testing::test_dir("sheet");
    const testing::CliResult result =
        run_cli({"replay", (s_dir / "gpu.h5").string(), "-o", out.string(), "--size", "640x360", "--contact-sheet",
                 (out / "sheet.png").string(), "--sheet-frames", "collisions", "--sheet-count", "6"},
                out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const Image sheet = read_png(out / "sheet.png");
    ASSERT_GT(sheet.width, 0);
    // four tiles in the first row, each the frame's scene part at most 400 pixels wide
    const int tile = std::min(400, replays::frame_layout(640, 360, replays::k_layer_all).scene.w);
    EXPECT_GT(sheet.width, 4 * tile);
    EXPECT_LT(sheet.width, 4 * tile + 100);
    EXPECT_GT(count_pixels(sheet, {0, 0, sheet.width, sheet.height}, testing::is_collision_colour), 100u);
    EXPECT_NE(result.out.find("contact sheet: "), std::string::npos) << result.out;
}

TEST_F(Replay, DiffHighlightsAPlantedPairDifference) {
    const std::filesystem::path out = testing::test_dir("diff");
    std::filesystem::copy_file(s_dir / "gpu.h5", out / "a.h5");
    std::filesystem::copy_file(s_dir / "gpu.h5", out / "b.h5");
    std::uint32_t frame = 0;
    std::uint64_t element = 0;
    std::uint32_t next_triangle = 0;
    {
        const recorder::Recording recording(out / "b.h5");
        const KnownRows rows = known_rows(recording);
        ASSERT_NE(rows.colliding, UINT64_MAX);
        frame = recording.frame_indices()[rows.colliding];
        const std::vector<std::uint64_t> offsets = recording.read_u64("/collisions/offsets");
        const TrianglePair last = recording.pairs(rows.colliding).back();
        const std::size_t triangles = recording.triangles(last.obj_b, recording.topology_at(last.obj_b, frame)).size();
        ASSERT_LT(last.tri_b + 1, triangles);
        element = offsets[rows.colliding + 1] - 1;
        next_triangle = last.tri_b + 1;
    }
    // The frame's last pair names the next triangle of its second object instead: still sorted.
    testing::overwrite_pair_element(out / "b.h5", element, 3, next_triangle);
    const std::string frames = std::to_string(frame);
    const testing::CliResult same = run_cli({"replay", "--diff", "a.h5", "a.h5", "-o", "same", "--size", "640x300", "--frames", frames}, out);
    EXPECT_EQ(same.exit_code, 0) << same.err;
    const testing::CliResult differ = run_cli({"replay", "--diff", "a.h5", "b.h5", "-o", "differ", "--size", "640x300", "--frames", frames}, out);
    EXPECT_EQ(differ.exit_code, 1) << differ.err;
    EXPECT_NE(differ.out.find("1 pairs only in a.h5, 1 only in b.h5"), std::string::npos) << differ.out;
    char name[32];
    std::snprintf(name, sizeof name, "diff_%04u.png", frame);
    const Image plain = read_png(out / "same" / name);
    const Image planted = read_png(out / "differ" / name);
    ASSERT_EQ(plain.width, 640);
    ASSERT_EQ(planted.width, 640);
    const replays::Rect left = {0, 0, 320, 300};
    const replays::Rect right = {320, 0, 320, 300};
    // The legend swatch is green in both; the meshes are green only where pairs differ.
    const std::uint64_t legend_green = count_pixels(plain, {0, 0, 640, 300}, testing::is_diff_colour);
    EXPECT_GT(count_pixels(planted, left, testing::is_diff_colour) + count_pixels(planted, right, testing::is_diff_colour),
              legend_green + 20);
    EXPECT_GT(count_pixels(planted, right, testing::is_diff_colour), 10u);
    // Recordings of another scene do not compare.
    testing::record("C:small", "aabb", out / "other.h5", {"--frames", "0:2"});
    const testing::CliResult other = run_cli({"replay", "--diff", "a.h5", "other.h5", "-o", "other"}, out);
    EXPECT_EQ(other.exit_code, 2);
    EXPECT_NE(other.err.find("different scenes"), std::string::npos) << other.err;
}

TEST_F(Replay, ARecordingWithoutDepthBuffersReplaysWithoutThumbnailsAndSaysSo) {
    const std::filesystem::path out = testing::test_dir("no_depth");
    const testing::CliResult result = run_cli(
        {"replay", (s_dir / "gpu.h5").string(), "-o", out.string(), "--size", "800x450", "--frames", "10"}, out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.err.find("no depth buffers in this recording"), std::string::npos) << result.err;
    const Image image = read_png(out / frame_name(10));
    const replays::FrameLayout layout = replays::frame_layout(800, 450, replays::k_layer_all);
    // No thumbnail: where they go, the depth column holds text only (the colour bar and the view
    // matrix sit at its bottom).
    const replays::Rect thumbnails = {layout.depth.x, layout.depth.y + layout.depth.h / 10, layout.depth.w, layout.depth.h / 2};
    EXPECT_LT(count_pixels(image, thumbnails, viridis_like), 50u);
}

TEST_F(Replay, ARecordingWithDepthBuffersShowsThumbnails) {
    const std::filesystem::path out = testing::test_dir("depth");
    testing::record(k_scene, "gpu", out / "depth.h5", {"--depth", "every:1", "--frames", "8:12"});
    {
        const recorder::Recording recording(out / "depth.h5");
        ASSERT_FALSE(recording.depth_images(0).empty()) << "record --depth every:1 stored no depth image";
    }
    const testing::CliResult result =
        run_cli({"replay", (out / "depth.h5").string(), "-o", out.string(), "--size", "800x450", "--frames", "8"}, out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err.find("no depth buffers"), std::string::npos) << result.err;
    const Image image = read_png(out / frame_name(8));
    const replays::FrameLayout layout = replays::frame_layout(800, 450, replays::k_layer_all);
    const replays::Rect thumbnails = {layout.depth.x, layout.depth.y + layout.depth.h / 10, layout.depth.w, layout.depth.h / 2};
    EXPECT_GT(count_pixels(image, thumbnails, viridis_like), 2000u);
}

TEST_F(Replay, DecisionsShowWhenRecordedAndAreSaidMissingOtherwise) {
    const std::filesystem::path out = testing::test_dir("decision");
    testing::record(k_scene, "adaptive", out / "adaptive.h5", {"--frames", "8:12"});
    {
        const recorder::Recording recording(out / "adaptive.h5");
        ASSERT_FALSE(recording.frame_values("decision").empty()) << "record --method adaptive stored no decisions";
    }
    const testing::CliResult adaptive =
        run_cli({"replay", (out / "adaptive.h5").string(), "-o", (out / "a").string(), "--size", "800x450"}, out);
    ASSERT_EQ(adaptive.exit_code, 0) << adaptive.err;
    EXPECT_EQ(adaptive.err.find("no decisions"), std::string::npos) << adaptive.err;
    const testing::CliResult gpu = run_cli(
        {"replay", (s_dir / "gpu.h5").string(), "-o", (out / "g").string(), "--size", "800x450", "--frames", "8:12"}, out);
    ASSERT_EQ(gpu.exit_code, 0) << gpu.err;
    EXPECT_NE(gpu.err.find("no decisions in this recording"), std::string::npos) << gpu.err;
    // The decision's lines make the panel hold more text than "not recorded" does.
    const replays::FrameLayout layout = replays::frame_layout(800, 450, replays::k_layer_all);
    const replays::Rect decision = {layout.panel.x, layout.panel.y, layout.panel.w, layout.panel.h / 4};
    const std::uint64_t with = count_pixels(read_png(out / "a" / frame_name(8)), decision, testing::is_bright);
    const std::uint64_t without = count_pixels(read_png(out / "g" / frame_name(8)), decision, testing::is_bright);
    EXPECT_GT(with, without + 100) << with << " vs " << without;
}

TEST(ReplayErrors, ACorruptRecordingIsOneLineNamingTheFileAndExit2) {
    const std::filesystem::path out = testing::test_dir("corrupt");
    testing::record(k_scene, "aabb", out / "good.h5", {"--frames", "0:4"});
    const std::string bytes = testing::read_bytes(out / "good.h5");
    std::ofstream(out / "truncated.h5", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 3));
    std::ofstream(out / "garbage.h5", std::ios::binary) << "not an HDF5 file at all";
    for (const char* file : {"truncated.h5", "garbage.h5", "missing.h5"}) {
        const testing::CliResult result = run_cli({"replay", file, "-o", "frames"}, out);
        EXPECT_EQ(result.exit_code, 2) << file;
        ASSERT_EQ(result.err_lines().size(), 1u) << result.err;
        EXPECT_EQ(result.err.rfind("collidescope: error: ", 0), 0u) << result.err;
        EXPECT_NE(result.err.find(file), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(out / "frames" / "frame_0000.png")) << file;
    }
}

TEST(ReplayErrors, BadOptionsAreUsageErrors) {
    const std::filesystem::path out = testing::test_dir("options");
    testing::record(k_scene, "aabb", out / "run.h5", {"--frames", "0:2"});
    const std::vector<std::vector<std::string>> bad = {
        {"--size", "12x"}, {"--camera", "fixed:1,2"}, {"--show", "meshes,bogus"}, {"--frames", "40:50"},
        {"--sheet-frames", "fastest", "--contact-sheet", "s.png"}, {"--diff"}};
    for (const std::vector<std::string>& extra : bad) {
        std::vector<std::string> args = {"replay", "run.h5", "-o", "frames"};
        args.insert(args.end(), extra.begin(), extra.end());
        const testing::CliResult result = run_cli(args, out);
        EXPECT_EQ(result.exit_code, 2) << extra[0];
        EXPECT_EQ(result.err_lines().size(), 1u) << result.err;
    }
}

}  // namespace
}  // namespace collidescope
