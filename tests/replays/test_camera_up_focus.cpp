// The camera's up axis (--up, the recording's up_axis) and --camera focus: the up axis points
// up on screen in every camera mode; focus frames the colliding triangles, much larger than
// auto does, and moves smoothly from frame to frame.

#include "replay_helpers.hpp"

#include "support/cli_runner.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/replays/camera.hpp"
#include "collidescope/scene.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>

namespace collidescope {
namespace {

using Vec = std::array<double, 3>;

replays::Bounds cube(double lo, double hi) {
    replays::Bounds box;
    box.add(lo, lo, lo);
    box.add(hi, hi, hi);
    return box;
}

Vec axis_vector(char axis) { return {axis == 'x' ? 1.0 : 0.0, axis == 'y' ? 1.0 : 0.0, axis == 'z' ? 1.0 : 0.0}; }

// A point a little along the up axis from the target projects straight above it on screen.
void expect_up_on_screen(const replays::Camera& camera, char up, const std::string& what) {
    const Vec up_vector = axis_vector(up);
    const auto at = camera.project(camera.target[0], camera.target[1], camera.target[2]);
    const auto above = camera.project(camera.target[0] + 0.1 * up_vector[0], camera.target[1] + 0.1 * up_vector[1],
                                      camera.target[2] + 0.1 * up_vector[2]);
    const double dx = above[0] - at[0];
    const double dy = above[1] - at[1];
    EXPECT_LT(dy, 0) << what << ": up goes down the screen";
    EXPECT_LT(std::abs(dx), 1e-6 * std::abs(dy) + 1e-9) << what << ": up leans sideways";
}

TEST(CameraUp, TheUpAxisPointsUpOnScreenInEveryMode) {
    const replays::Bounds box = cube(-1, 3);
    const replays::Rect viewport{0, 0, 640, 360};
    for (const char up : {'x', 'y', 'z'}) {
        for (const char* mode : {"auto", "orbit", "focus", "fixed:7,5,9:1,1,1"}) {
            replays::CameraSpec spec = replays::parse_camera(mode);
            spec.up = up;
            for (std::uint64_t ordinal : {0u, 3u, 7u}) {
                const replays::Framing region{{2, 2, 2}, 0.5};
                const replays::Camera camera = replays::make_camera(spec, box, viewport, ordinal, 10, &region);
                EXPECT_EQ(camera.up, axis_vector(up));
                expect_up_on_screen(camera, up, std::string(mode) + " up " + up + " frame " + std::to_string(ordinal));
                // What the camera frames stays in view: the box's centre, or the focus region.
                const bool focus = spec.kind == replays::CameraSpec::Kind::Focus;
                const auto centre = focus ? camera.project(2, 2, 2) : camera.project(1, 1, 1);
                EXPECT_TRUE(viewport.contains(centre[0], centre[1])) << mode << " up " << up;
            }
        }
    }
}

TEST(CameraUp, NoUpAxisIsZAsBefore) {
    const replays::Bounds box = cube(0, 2);
    replays::CameraSpec none = replays::parse_camera("auto");
    replays::CameraSpec z = none;
    z.up = 'z';
    const replays::Camera a = replays::make_camera(none, box, {0, 0, 320, 200}, 0, 1);
    const replays::Camera b = replays::make_camera(z, box, {0, 0, 320, 200}, 0, 1);
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.up, (Vec{0, 0, 1}));
}

TEST(CameraUp, ParsesXYZOnly) {
    EXPECT_EQ(replays::parse_up_axis("y"), 'y');
    EXPECT_THROW(replays::parse_up_axis("Y"), InputError);
    EXPECT_THROW(replays::parse_up_axis("up"), InputError);
}

// 80 frames in a 10-unit cube; collisions in a 0.2-unit box near a corner in frames 30-49,
// then none (the camera holds, then eases back).
std::vector<replays::Bounds> corner_collisions() {
    std::vector<replays::Bounds> colliding(80);
    for (std::size_t k = 30; k < 50; ++k) {
        const double drift = 0.01 * double(k);
        colliding[k].add(8.0 + drift, 8.0, 1.0);
        colliding[k].add(8.2 + drift, 8.2, 1.2);
    }
    return colliding;
}

TEST(FocusPath, FramesTheCollisionsAndReturnsToTheScene) {
    const replays::Bounds whole = cube(0, 10);
    const auto colliding = corner_collisions();
    const std::vector<replays::Framing> path = replays::focus_path(colliding, whole);
    ASSERT_EQ(path.size(), colliding.size());
    const double scene_radius = 0.5 * std::sqrt(3.0) * 10;
    // Mid-collision: close to the collision box, a small region.
    const replays::Framing& mid = path[40];
    EXPECT_NEAR(mid.center[0], 8.1 + 0.4, 0.3);
    EXPECT_NEAR(mid.center[1], 8.1, 0.3);
    EXPECT_NEAR(mid.center[2], 1.1, 0.3);
    EXPECT_LT(mid.radius, 0.1 * scene_radius);
    // Long before and long after: the whole scene.
    for (const std::size_t k : {0u, 79u}) {
        EXPECT_NEAR(path[k].radius, scene_radius, 0.05 * scene_radius) << k;
        EXPECT_NEAR(path[k].center[0], 5, 0.2) << k;
    }
    // Just after the last collision (held): still near the region.
    EXPECT_LT(path[52].radius, 0.2 * scene_radius);
}

TEST(FocusPath, ConsecutiveFramesMoveBoundedly) {
    const replays::Bounds whole = cube(0, 10);
    const replays::FocusSettings settings;
    const std::vector<replays::Framing> path = replays::focus_path(corner_collisions(), whole, settings);
    const double diagonal = std::sqrt(3.0) * 10;
    const double log_range = std::log(0.5 * diagonal) - std::log(settings.min_fraction * 0.5 * diagonal);
    double largest_step = 0;
    for (std::size_t k = 1; k < path.size(); ++k) {
        double squared = 0;
        for (int i = 0; i < 3; ++i) squared += std::pow(path[k].center[i] - path[k - 1].center[i], 2);
        largest_step = std::max(largest_step, std::sqrt(squared));
        EXPECT_LE(std::abs(std::log(path[k].radius / path[k - 1].radius)), settings.smoothing * log_range + 1e-9) << k;
    }
    EXPECT_LE(largest_step, settings.smoothing * diagonal);
    // Without smoothing the camera would jump 6+ units in one frame; smoothed it does not.
    replays::FocusSettings raw = settings;
    raw.smoothing = 1;
    const std::vector<replays::Framing> jumpy = replays::focus_path(corner_collisions(), whole, raw);
    double raw_step = 0;
    for (std::size_t k = 1; k < jumpy.size(); ++k) {
        double squared = 0;
        for (int i = 0; i < 3; ++i) squared += std::pow(jumpy[k].center[i] - jumpy[k - 1].center[i], 2);
        raw_step = std::max(raw_step, std::sqrt(squared));
    }
    EXPECT_GT(raw_step, 5.0);
    EXPECT_LT(largest_step, 0.5 * raw_step);
}

// Red (collision colour) pixels of frame `frame`'s PNG and of the contact sheet, under `camera`.
std::pair<std::uint64_t, std::uint64_t> red_pixels(const std::filesystem::path& recording, const std::filesystem::path& out,
                                                   std::uint32_t frame, const std::string& camera) {
    std::filesystem::create_directories(out);
    const testing::CliResult result =
        testing::run_cli({"replay", recording.string(), "-o", out.string(), "--size", "480x270", "--show",
                          "meshes,collisions", "--camera", camera, "--threads", "2", "--contact-sheet",
                          (out / "sheet.png").string()},
                         out);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.png", frame);
    const testing::Image image = testing::read_png(out / name);
    const testing::Image sheet = testing::read_png(out / "sheet.png");
    return {testing::count_pixels(image, {0, 0, image.width, image.height}, testing::is_collision_colour),
            testing::count_pixels(sheet, {0, 0, sheet.width, sheet.height}, testing::is_collision_colour)};
}

// A 10 x 10 floor at z = 0 and a small upright triangle piercing it near one corner, moving
// along x over 8 frames, plus a sheet high above: collisions a tiny part of a large scene.
Scene pin_through_floor() {
    std::vector<std::vector<MeshData>> frames;
    for (int f = 0; f < 8; ++f) {
        const double x = 8.3 + 0.02 * f;
        MeshData pin;
        pin.vertices = {Vec3(x, 8.5, -0.2), Vec3(x + 0.3, 8.5, -0.2), Vec3(x + 0.15, 8.52, 0.25)};
        pin.triangles = {{0, 1, 2}};
        frames.push_back({testing::grid_sheet(10, 10.0), pin, testing::grid_sheet(4, 10.0, Vec3(0, 0, 6))});
    }
    Scene scene;
    scene.name = "pin";
    scene.source = make_memory_source({"floor", "pin", "ceiling"}, std::move(frames));
    return scene;
}

TEST(CameraFocus, FramesTheCollisionsMuchLargerThanAuto) {
    const std::filesystem::path dir = testing::test_dir("focus_" + std::to_string(::getpid()));
    const std::vector<std::string> patterns = testing::write_scene_files(pin_through_floor(), dir);
    std::vector<std::string> args = {"record"};
    args.insert(args.end(), patterns.begin(), patterns.end());
    args.insert(args.end(), {"--method", "aabb", "-o", "run.h5", "-q"});
    const testing::CliResult recorded = testing::run_cli(args, dir);
    ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
    const recorder::Recording recording(dir / "run.h5");
    for (const std::uint64_t pairs : recording.pair_counts()) ASSERT_GT(pairs, 0u) << "the pin pierces the floor in every frame";
    const auto [with_auto, sheet_auto] = red_pixels(dir / "run.h5", dir / "auto", 4, "auto");
    const auto [with_focus, sheet_focus] = red_pixels(dir / "run.h5", dir / "focus", 4, "focus");
    EXPECT_GT(with_auto, 0u);
    EXPECT_GT(with_focus, 10 * with_auto) << "auto " << with_auto << ", focus " << with_focus;
    std::printf("red pixels in frame 4: auto %llu, focus %llu; on the contact sheet: auto %llu, focus %llu\n",
                static_cast<unsigned long long>(with_auto), static_cast<unsigned long long>(with_focus),
                static_cast<unsigned long long>(sheet_auto), static_cast<unsigned long long>(sheet_focus));
    // The contact sheet shows the frames as rendered: in focus too.
    EXPECT_GT(sheet_focus, 10 * sheet_auto) << "auto " << sheet_auto << ", focus " << sheet_focus;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

// One frame's PNG bytes of `recording` with `extra` options.
std::string frame_bytes(const std::filesystem::path& dir, const std::string& recording, const std::string& out,
                        std::vector<std::string> extra) {
    std::vector<std::string> args = {"replay", recording, "-o", out, "--size", "200x150", "--frames", "3", "--show", "meshes"};
    args.insert(args.end(), extra.begin(), extra.end());
    const testing::CliResult result = testing::run_cli(args, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return testing::read_bytes(dir / out / "frame_0003.png");
}

TEST(CameraUp, TheRecordedUpAxisIsTheDefaultAndUpOverridesIt) {
    const std::filesystem::path dir = testing::test_dir("up_" + std::to_string(::getpid()));
    testing::record("demo:small", "aabb", dir / "plain.h5", {"--frames", "0:5"});
    std::filesystem::copy_file(dir / "plain.h5", dir / "y_up.h5");
    testing::set_time_attributes(dir / "y_up.h5", 30.0, 'y');
    const std::string plain = frame_bytes(dir, "plain.h5", "a", {});
    const std::string recorded_y = frame_bytes(dir, "y_up.h5", "b", {});
    const std::string asked_y = frame_bytes(dir, "plain.h5", "c", {"--up", "y"});
    const std::string overridden_z = frame_bytes(dir, "y_up.h5", "d", {"--up", "z"});
    ASSERT_FALSE(plain.empty());
    EXPECT_EQ(recorded_y, asked_y) << "the recording's up_axis y is --up y";
    EXPECT_EQ(overridden_z, plain) << "--up z overrides the recording's y: as a recording without one";
    EXPECT_NE(recorded_y, plain);
    const testing::CliResult bad = testing::run_cli({"replay", "plain.h5", "-o", "e", "--up", "w"}, dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err_lines().size(), 1u) << bad.err;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace collidescope
