// replay --contact-moments (record --between-frames): one contact_NNNN.png per replayed interval
// with a pass-through, showing the ring and outlines of the first pair in the pass-through colour
// where the frame's own image has none; the meshes there are neither frame's (interpolated);
// the timeline's ticks on every image; its errors without intervals or without -o.

#include "replay_helpers.hpp"

#include "support/cli_runner.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/replays/options.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

namespace collidescope {
namespace {

// The pass-through colour (overlay_moment.cpp), as drawn: magenta.
bool is_pass_through_colour(const std::uint8_t* p) { return p[0] > 200 && p[1] < 110 && p[2] > 170; }

std::filesystem::path png(const std::filesystem::path& dir, const char* prefix, std::uint32_t frame) {
    char name[40];
    std::snprintf(name, sizeof name, "%s_%04u.png", prefix, frame);
    return dir / name;
}

TEST(ReplayBetweenFrames, EachPassThroughIntervalGetsItsMomentOfContact) {
    const std::filesystem::path dir = testing::test_dir("between_" + std::to_string(::getpid()));
    testing::record("demo", "aabb", dir / "run.h5", {"--frames", "15:24", "--between-frames"});
    const recorder::Recording recording(dir / "run.h5");
    std::vector<std::uint32_t> expected;  // first frames of the intervals with a pass-through
    for (std::uint64_t row = 1; row < recording.frames_complete(); ++row) {
        const recorder::RecordedInterval interval = recording.interval(row, false);
        if (interval.stats.pass_throughs > 0) expected.push_back(interval.from_frame);
    }
    ASSERT_FALSE(expected.empty());
    ASSERT_LT(expected.size(), recording.frames_complete() - 1) << "some interval should have none";
    const testing::CliResult result =
        testing::run_cli({"replay", "run.h5", "-o", "out", "--size", "800x450", "--contact-moments", "-q"}, dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("moments of contact: " + std::to_string(expected.size())), std::string::npos) << result.out;
    const replays::FrameLayout layout = replays::frame_layout(800, 450, replays::k_layer_all);
    for (std::uint32_t frame = 15; frame < 24; ++frame) {
        const bool moment = std::find(expected.begin(), expected.end(), frame) != expected.end();
        ASSERT_EQ(std::filesystem::exists(png(dir / "out", "contact", frame)), moment) << "frame " << frame;
        const testing::Image own = testing::read_png(png(dir / "out", "frame", frame));
        // The timeline ticks every pass-through interval on every image.
        EXPECT_GT(testing::count_pixels(own, layout.timeline, is_pass_through_colour), 0u) << "frame " << frame;
        EXPECT_EQ(testing::count_pixels(own, layout.scene, is_pass_through_colour), 0u) << "frame " << frame;
        if (!moment) continue;
        const testing::Image image = testing::read_png(png(dir / "out", "contact", frame));
        const std::uint64_t ring = testing::count_pixels(image, layout.scene, is_pass_through_colour);
        std::printf("frames %u-%u: %llu pass-through-coloured pixels in the scene\n", frame, frame + 1,
                    static_cast<unsigned long long>(ring));
        EXPECT_GT(ring, 200u) << "frame " << frame;
        // Interpolated: the scene differs from both frames' images.
        const testing::Image next = testing::read_png(png(dir / "out", "frame", frame + 1));
        const auto differs = [&](const testing::Image& other) {
            std::uint64_t n = 0;
            for (int y = layout.scene.y; y < layout.scene.y + layout.scene.h; ++y) {
                for (int x = layout.scene.x; x < layout.scene.x + layout.scene.w; ++x) {
                    const std::size_t at = 4 * (std::size_t(y) * 800 + std::size_t(x));
                    n += std::equal(&image.rgba[at], &image.rgba[at] + 3, &other.rgba[at]) ? 0 : 1;
                }
            }
            return n;
        };
        EXPECT_GT(differs(own), 500u) << "frame " << frame;
        EXPECT_GT(differs(next), 500u) << "frame " << frame;
    }
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(ReplayBetweenFrames, ErrorsNameWhatIsMissing) {
    const std::filesystem::path dir = testing::test_dir("between_errors_" + std::to_string(::getpid()));
    testing::record("C:small", "aabb", dir / "plain.h5", {"--frames", "0:3"});
    const testing::CliResult plain = testing::run_cli({"replay", "plain.h5", "-o", "out", "--contact-moments"}, dir);
    EXPECT_EQ(plain.exit_code, 2);
    EXPECT_NE(plain.err.find("needs a recording made with record --between-frames"), std::string::npos) << plain.err;
    testing::record("C:small", "aabb", dir / "run.h5", {"--frames", "0:3", "--between-frames"});
    const testing::CliResult no_dir = testing::run_cli({"replay", "run.h5", "--video", "x.mp4", "--contact-moments"}, dir);
    EXPECT_EQ(no_dir.exit_code, 2);
    EXPECT_NE(no_dir.err.find("--contact-moments writes PNGs"), std::string::npos) << no_dir.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.mp4"));
    const testing::CliResult diff = testing::run_cli({"replay", "--diff", "run.h5", "run.h5", "-o", "d", "--contact-moments"}, dir);
    EXPECT_EQ(diff.exit_code, 2);
    EXPECT_NE(diff.err.find("not with --diff"), std::string::npos) << diff.err;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace collidescope
