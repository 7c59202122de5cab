// replay --video: the clip decoded back with libavformat/libavcodec has one frame per replayed
// frame, the requested size, and each frame closest to the PNG of the same frame; bad names
// and unwritable places are one-line errors that leave no file behind.

#include "replay_helpers.hpp"
#include "video_decode.hpp"

#include "support/cli_runner.hpp"

#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <regex>

namespace collidescope {
namespace {

using testing::run_cli;

class Video : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = testing::test_dir("video_suite_" + std::to_string(::getpid()));
        testing::record("demo:small", "aabb", s_dir / "run.h5");
    }
    static void TearDownTestSuite() { std::filesystem::remove_all(s_dir); }
    static std::filesystem::path s_dir;
};
std::filesystem::path Video::s_dir;

// Files in `dir` whose name holds "partial" (a temporary clip left behind).
std::size_t partial_files(const std::filesystem::path& dir) {
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        count += entry.path().filename().string().find("partial") != std::string::npos ? 1 : 0;
    }
    return count;
}

// Each decoded frame of a clip of frames 2..8 is within `tolerance` of that frame's PNG and
// closer to it than to any other frame's: a clip that froze or repeated a frame fails.
void expect_each_frame_is_its_png(const testing::DecodedVideo& video, const std::filesystem::path& frames, double tolerance) {
    std::vector<std::vector<std::uint8_t>> pngs;
    for (int frame = 2; frame <= 8; ++frame) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", frame);
        pngs.push_back(testing::read_png(frames / name).rgba);
    }
    const std::vector<testing::FrameMatch> matches = testing::match_frames(video, pngs);
    ASSERT_EQ(matches.size(), pngs.size());
    for (std::size_t k = 0; k < matches.size(); ++k) {
        std::printf("%s frame %zu: closest to frame %zu's PNG, %.3f of 255 on average\n",
                    video.codec.c_str(), k, matches[k].closest + 2, matches[k].difference);
        EXPECT_EQ(matches[k].closest, k) << "decoded frame " << k << " is closest to frame " << matches[k].closest + 2
                                         << "'s PNG, not frame " << k + 2 << "'s";
        EXPECT_LT(matches[k].difference, tolerance) << "decoded frame " << k;
    }
}

// Where the four bytes of an MP4 box type first occur in the file (npos: nowhere).
std::size_t box_offset(const std::string& bytes, const char* type) { return bytes.find(type); }

TEST_F(Video, Mp4DecodesToOneFramePerReplayedFrameCloseToThePngs) {
    const std::filesystem::path out = testing::test_dir("video_mp4");
    const testing::CliResult result = run_cli({"replay", (s_dir / "run.h5").string(), "-o", (out / "frames").string(),
                                               "--video", (out / "clip.mp4").string(), "--size", "320x200", "--frames", "2:9"},
                                              out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("video: "), std::string::npos) << result.out;
    const testing::DecodedVideo video = testing::decode_video(out / "clip.mp4");
    ASSERT_TRUE(video.opened) << video.error;
    EXPECT_EQ(video.codec, "h264");
    EXPECT_EQ(video.pixel_format, "yuv420p");
    EXPECT_EQ(video.profile, "High");
    EXPECT_EQ(video.frames, 7u);
    EXPECT_EQ(video.width, 320);
    EXPECT_EQ(video.height, 200);
    EXPECT_NEAR(video.fps, 30.0, 1e-6) << "a recording without fps plays at 30";
    ASSERT_EQ(testing::read_png(out / "frames" / "frame_0002.png").width, 320);
    expect_each_frame_is_its_png(video, out / "frames", 6.0);
    // Playable while it downloads: the index (moov) before the media (mdat).
    const std::string bytes = testing::read_bytes(out / "clip.mp4");
    ASSERT_NE(box_offset(bytes, "moov"), std::string::npos);
    EXPECT_LT(box_offset(bytes, "moov"), box_offset(bytes, "mdat"));
    EXPECT_EQ(partial_files(out), 0u);
}

TEST_F(Video, GifDecodesToOneFramePerReplayedFrameCloseToThePngs) {
    const std::filesystem::path out = testing::test_dir("video_gif");
    const testing::CliResult result = run_cli({"replay", (s_dir / "run.h5").string(), "-o", (out / "frames").string(),
                                               "--video", (out / "clip.gif").string(), "--size", "320x200", "--frames", "2:9"},
                                              out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const testing::DecodedVideo video = testing::decode_video(out / "clip.gif");
    ASSERT_TRUE(video.opened) << video.error;
    EXPECT_EQ(video.codec, "gif");
    EXPECT_EQ(video.frames, 7u);
    EXPECT_EQ(video.width, 320);
    EXPECT_EQ(video.height, 200);
    ASSERT_EQ(testing::read_png(out / "frames" / "frame_0002.png").width, 320);
    expect_each_frame_is_its_png(video, out / "frames", 6.0);
    EXPECT_EQ(partial_files(out), 0u);
}

TEST_F(Video, VideoAloneWritesNoPngsAndOddSizesGrowToEven) {
    const std::filesystem::path out = testing::test_dir("video_alone");
    const testing::CliResult result = run_cli(
        {"replay", (s_dir / "run.h5").string(), "--video", "clip.mp4", "--size", "201x131", "--frames", "0:3"}, out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.find("wrote "), std::string::npos) << result.out;
    std::size_t pngs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) pngs += entry.path().extension() == ".png" ? 1 : 0;
    EXPECT_EQ(pngs, 0u);
    const testing::DecodedVideo video = testing::decode_video(out / "clip.mp4");
    ASSERT_TRUE(video.opened) << video.error;
    EXPECT_EQ(video.frames, 3u);
    EXPECT_EQ(video.width, 202);
    EXPECT_EQ(video.height, 132);
}

TEST_F(Video, TheClipPlaysAtTheRecordingsFps) {
    const std::filesystem::path out = testing::test_dir("video_fps");
    std::filesystem::copy_file(s_dir / "run.h5", out / "timed.h5");
    testing::set_time_attributes(out / "timed.h5", 24.0, 'z');
    const testing::CliResult result =
        run_cli({"replay", "timed.h5", "--video", "clip.mp4", "--size", "160x120", "--frames", "0:4"}, out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const testing::DecodedVideo video = testing::decode_video(out / "clip.mp4");
    ASSERT_TRUE(video.opened) << video.error;
    EXPECT_NEAR(video.fps, 24.0, 1e-6);
    EXPECT_EQ(video.frames, 4u);
}

TEST_F(Video, FrameTimesWithoutFpsGiveTheRateOfTheirMedianStep) {
    const std::filesystem::path out = testing::test_dir("video_times");
    std::filesystem::copy_file(s_dir / "run.h5", out / "timed.h5");
    const std::uint64_t rows = recorder::Recording(out / "timed.h5").frames_complete();  // closed again
    // Steps of 1/12 s but one of 0.3 s after row 2: the median ignores it.
    std::vector<double> times;
    for (std::uint64_t r = 0; r < rows; ++r) times.push_back(double(r) / 12.0 + (r >= 3 ? 0.3 : 0.0));
    testing::add_frame_times(out / "timed.h5", times);
    const testing::CliResult result =
        run_cli({"replay", "timed.h5", "--video", "clip.mp4", "--size", "160x120", "--frames", "0:6"}, out);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const testing::DecodedVideo video = testing::decode_video(out / "clip.mp4");
    ASSERT_TRUE(video.opened) << video.error;
    EXPECT_NEAR(video.fps, 12.0, 1e-3);
}

TEST_F(Video, BadNamesAndUnwritablePlacesAreOneLineErrorsThatLeaveNoFile) {
    const std::filesystem::path out = testing::test_dir("video_errors");
    std::ofstream(out / "plain_file") << "not a directory";
    const std::vector<std::string> bad = {"clip.avi", "clip", "missing_dir/clip.mp4", "plain_file/clip.gif"};
    for (const std::string& name : bad) {
        const testing::CliResult result =
            run_cli({"replay", (s_dir / "run.h5").string(), "--video", name, "--size", "160x120", "--frames", "0:2"}, out);
        EXPECT_EQ(result.exit_code, 2) << name;
        ASSERT_EQ(result.err_lines().size(), 1u) << name << ": " << result.err;
        EXPECT_NE(result.err.find(name), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(out / name)) << name;
    }
    EXPECT_EQ(partial_files(out), 0u);
    // With --diff: not supported, said so.
    const testing::CliResult diff = run_cli(
        {"replay", "--diff", (s_dir / "run.h5").string(), (s_dir / "run.h5").string(), "-o", "d", "--video", "x.mp4"}, out);
    EXPECT_EQ(diff.exit_code, 2);
    EXPECT_EQ(diff.err_lines().size(), 1u) << diff.err;
    // Neither -o nor --video: nothing to write.
    const testing::CliResult nothing = run_cli({"replay", (s_dir / "run.h5").string()}, out);
    EXPECT_EQ(nothing.exit_code, 2);
    EXPECT_EQ(nothing.err_lines().size(), 1u) << nothing.err;
}

TEST_F(Video, AReplayThatFailsMidwayLeavesNoHalfWrittenClip) {
    // The first colliding frame names a triangle that does not exist: the frames before it are
    // already encoded when it fails.
    const std::filesystem::path out = testing::test_dir("video_failed");
    std::filesystem::copy_file(s_dir / "run.h5", out / "bad.h5");
    testing::overwrite_pair_element(out / "bad.h5", 0, 1, 4000000000u);
    const testing::CliResult result = run_cli({"replay", "bad.h5", "--video", "clip.mp4", "--size", "160x120"}, out);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.err_lines().size(), 1u) << result.err;
    EXPECT_NE(result.err.find("out of range"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out / "clip.mp4"));
    EXPECT_EQ(partial_files(out), 0u);
}

TEST(VideoInterrupt, SigintStopsBetweenFramesAndRemovesTheUnfinishedClip) {
    const std::filesystem::path out = testing::test_dir("video_sigint_" + std::to_string(::getpid()));
    testing::record("demo", "aabb", out / "run.h5");  // 60 frames: several seconds at 1920x1080, one thread
    testing::CliProcess replay({"replay", "run.h5", "--video", "clip.mp4", "--size", "1920x1080", "--threads", "1"}, out);
    ASSERT_TRUE(replay.wait_until([&] { return std::filesystem::exists(out / ".clip.mp4.partial"); }, 60))
        << replay.err();
    replay.send(SIGINT);
    const testing::CliResult result = replay.wait();
    EXPECT_EQ(result.exit_code, 130) << result.err;
    EXPECT_NE(result.err.find("interrupted by SIGINT; clip.mp4 not written"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out / "clip.mp4"));
    EXPECT_EQ(partial_files(out), 0u);
    if (!HasFailure()) std::filesystem::remove_all(out);
}

// Without --video too (mpirun's Ctrl-C reaches the ranks as SIGTERM, docs/how-to/mpi.md): the replay
// stops between frames, every PNG written is whole, and it says how many it rendered.
TEST(ReplayInterrupt, SigtermStopsBetweenFramesAndEveryPngIsComplete) {
    const std::filesystem::path out = testing::test_dir("replay_sigterm_" + std::to_string(::getpid()));
    testing::record("demo", "aabb", out / "run.h5");
    testing::CliProcess replay({"replay", "run.h5", "-o", "frames", "--size", "1920x1080", "--threads", "1"}, out);
    ASSERT_TRUE(replay.wait_until([&] { return std::filesystem::exists(out / "frames" / "frame_0002.png"); }, 60))
        << replay.err();
    replay.send(SIGTERM);
    const testing::CliResult result = replay.wait();
    EXPECT_EQ(result.exit_code, 143) << result.err;
    std::smatch match;
    const std::regex line("replay: interrupted by SIGTERM; ([0-9]+) of 60 frames rendered, every PNG in frames complete\n");
    ASSERT_TRUE(std::regex_search(result.err, match, line)) << result.err;
    std::size_t pngs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out / "frames")) {
        const std::string bytes = testing::read_text(entry.path());
        const std::string iend = std::string("IEND\xae\x42\x60\x82", 8);
        EXPECT_TRUE(bytes.size() > 8 && bytes.compare(bytes.size() - 8, 8, iend) == 0) << entry.path();
        ++pngs;
    }
    EXPECT_EQ(pngs, std::stoul(match[1]));
    EXPECT_LT(pngs, 60u);
    if (!HasFailure()) std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace collidescope
