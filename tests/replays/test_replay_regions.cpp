// The regions layer of replay (record --regions): the curves drawn in their colours over the
// scene, only when the layer is on; --camera region:ID framing one region (far more of its
// curve on screen than --camera auto); its errors without regions or with an unknown id.

#include "replay_helpers.hpp"

#include "support/cli_runner.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/replays/options.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>

namespace collidescope {
namespace {

// Region 1's colour (overlay_regions.cpp's palette), as drawn: a bright yellow.
bool is_region_one_colour(const std::uint8_t* p) { return p[0] > 220 && p[1] > 200 && p[2] < 90; }

// Region-1-coloured pixels in the scene of `frame` replayed with `extra` options.
std::uint64_t region_pixels(const std::filesystem::path& dir, const std::string& out, std::uint32_t frame,
                            std::vector<std::string> extra) {
    std::vector<std::string> args = {"replay", "run.h5", "-o", out, "--frames", std::to_string(frame), "--size", "800x450", "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    const testing::CliResult result = testing::run_cli(args, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.png", frame);
    const testing::Image image = testing::read_png(dir / out / name);
    const replays::Rect scene = replays::frame_layout(800, 450, replays::k_layer_all).scene;
    return testing::count_pixels(image, scene, is_region_one_colour);
}

TEST(ReplayRegions, CurvesAreDrawnOnlyWithTheLayerAndTheRegionCameraFramesOne) {
    const std::filesystem::path dir = testing::test_dir("regions_" + std::to_string(::getpid()));
    testing::record("C:small", "aabb", dir / "run.h5", {"--regions"});
    const recorder::Recording recording(dir / "run.h5");
    ASSERT_TRUE(recording.has_regions());
    // The first frame with region 1.
    std::uint32_t frame = UINT32_MAX;
    for (std::uint64_t row = 0; row < recording.frames_complete() && frame == UINT32_MAX; ++row) {
        for (const recorder::RecordedRegion& region : recording.regions(row)) {
            if (region.id == 1) frame = recording.frame_indices()[row];
        }
    }
    ASSERT_NE(frame, UINT32_MAX);
    const std::uint64_t with = region_pixels(dir, "with", frame, {"--show", "meshes,regions"});
    const std::uint64_t without = region_pixels(dir, "without", frame, {"--show", "meshes"});
    const std::uint64_t framed = region_pixels(dir, "framed", frame, {"--show", "meshes,regions", "--camera", "region:1"});
    std::printf("region 1 pixels at frame %u: layer off %llu, auto camera %llu, region camera %llu\n", frame,
                static_cast<unsigned long long>(without), static_cast<unsigned long long>(with),
                static_cast<unsigned long long>(framed));
    EXPECT_EQ(without, 0u);
    EXPECT_GT(with, 0u);
    EXPECT_GT(framed, 3 * with);
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(ReplayRegions, RegionCameraErrorsNameWhatIsMissing) {
    const std::filesystem::path dir = testing::test_dir("regions_errors_" + std::to_string(::getpid()));
    testing::record("C:small", "aabb", dir / "plain.h5");
    const testing::CliResult plain = testing::run_cli({"replay", "plain.h5", "-o", "out", "--camera", "region:1"}, dir);
    EXPECT_EQ(plain.exit_code, 2);
    EXPECT_NE(plain.err.find("needs a recording made with record --regions"), std::string::npos) << plain.err;
    testing::record("C:small", "aabb", dir / "run.h5", {"--regions"});
    const testing::CliResult unknown = testing::run_cli({"replay", "run.h5", "-o", "out", "--camera", "region:999"}, dir);
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.err.find("no such region"), std::string::npos) << unknown.err;
    const testing::CliResult bad = testing::run_cli({"replay", "run.h5", "-o", "out", "--camera", "region:0"}, dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("a region id is a whole number from 1"), std::string::npos) << bad.err;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace collidescope
