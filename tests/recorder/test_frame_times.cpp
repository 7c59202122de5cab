// Schema 1.4: the time of every frame (/frames/time, seconds), the fps, the clip and the up
// axis, written only when the scene's inputs say them. Scenes here carry times set by the test
// (what an animated model or a point cache fills in), recorded in-process as `record` does.

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/recorder/compare.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/recorder/validate.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace collidescope {
namespace {

using testing_files::TempDir;

// Frame k at 0.25 + k / fps seconds (a clip that starts a quarter second in).
Scene timed_scene(double fps, std::uint32_t frames) {
    Scene scene = testing::crossing_sheets(3, frames);
    for (std::uint32_t k = 0; k < frames; ++k) scene.frame_times.push_back(0.25 + k / fps);
    scene.fps = fps;
    scene.clip = "Armature|Walk";
    scene.up_axis = 'y';
    return scene;
}

bool has_root_attribute(const recorder::Recording& rec, const std::string& name) {
    const auto metadata = rec.metadata();
    return std::any_of(metadata.begin(), metadata.end(), [&](const auto& entry) { return entry.first == name; });
}

TEST(FrameTimes, TimesOfTheRecordedFramesComeBackWithFpsClipAndUpAxis) {
    TempDir dir;
    const Scene scene = timed_scene(24, 8);
    // Frames 2..6: the times are the scene frames', not the rows'.
    testing::record_in_process(scene, dir.path() / "run.h5", 2, 7, false);
    const recorder::Recording rec(dir.path() / "run.h5");
    ASSERT_TRUE(rec.has_frame_times());
    const std::vector<double> times = rec.frame_times();
    ASSERT_EQ(times.size(), 5u);
    for (std::uint32_t r = 0; r < times.size(); ++r) EXPECT_EQ(times[r], scene.frame_times[r + 2]) << "row " << r;
    EXPECT_EQ(rec.unit_of(recorder::schema::k_frame_time), "s");
    EXPECT_EQ(rec.fps(), 24.0);
    EXPECT_EQ(rec.clip(), "Armature|Walk");
    EXPECT_EQ(rec.up_axis(), 'y');
    EXPECT_EQ(rec.version_minor(), recorder::schema::k_version_minor);  // 1.4 or later: the times
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
}

TEST(FrameTimes, AnUntimedSceneWritesNothingNew) {
    TempDir dir;
    const Scene scene = testing::crossing_sheets(3, 5);
    testing::record_in_process(scene, dir.path() / "run.h5", 0, 5, false);
    const recorder::Recording rec(dir.path() / "run.h5");
    EXPECT_FALSE(rec.has_frame_times());
    EXPECT_TRUE(rec.frame_times().empty());
    EXPECT_EQ(rec.fps(), 0.0);
    EXPECT_EQ(rec.clip(), "");
    EXPECT_EQ(rec.up_axis(), 0);
    for (const char* name : {recorder::schema::k_attr_fps, recorder::schema::k_attr_clip, recorder::schema::k_attr_up_axis}) {
        EXPECT_FALSE(has_root_attribute(rec, name)) << name;
    }
    const auto paths = rec.dataset_paths();
    EXPECT_EQ(std::count(paths.begin(), paths.end(), recorder::schema::k_frame_time), 0);
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
}

TEST(FrameTimes, ValidateReportsTimesThatGoBackwards) {
    TempDir dir;
    Scene scene = timed_scene(30, 5);
    scene.frame_times[3] = 0.0;  // earlier than frame 2
    testing::record_in_process(scene, dir.path() / "run.h5", 0, 5, false);
    const recorder::Recording rec(dir.path() / "run.h5");
    const auto problems = recorder::validate_recording(rec).problems;
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("/frames/time"), std::string::npos) << problems[0];
    EXPECT_NE(problems[0].find("earlier"), std::string::npos) << problems[0];
}

TEST(FrameTimes, CompareNamesFramesSampledAtOtherTimes) {
    TempDir dir;
    testing::record_in_process(timed_scene(30, 4), dir.path() / "a.h5", 0, 4, false);
    testing::record_in_process(timed_scene(24, 4), dir.path() / "b.h5", 0, 4, false);
    testing::record_in_process(timed_scene(30, 4), dir.path() / "c.h5", 0, 4, false);
    const recorder::Recording a(dir.path() / "a.h5"), b(dir.path() / "b.h5"), c(dir.path() / "c.h5");
    const recorder::ComparisonReport ab = recorder::compare_recordings(a, b);
    EXPECT_TRUE(ab.both_timed);
    EXPECT_EQ(ab.time_differences, 3u);  // frame 0 is at 0.25 s in both
    ASSERT_TRUE(ab.first_time_difference.has_value());
    EXPECT_EQ(*ab.first_time_difference, 1u);
    const recorder::ComparisonReport ac = recorder::compare_recordings(a, c);
    EXPECT_EQ(ac.time_differences, 0u);
}

TEST(FrameTimes, InspectShowsTimeRangeFpsClipAndUpAxis) {
    TempDir dir;
    testing::record_in_process(timed_scene(24, 8), dir.path() / "run.h5", 0, 8, false);
    testing::record_in_process(testing::crossing_sheets(3, 3), dir.path() / "plain.h5", 0, 3, false);
    const testing::CliResult json = testing::run_cli({"inspect", "run.h5", "--json"}, dir.path());
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto info = nlohmann::json::parse(json.out);
    EXPECT_EQ(info["fps"].get<double>(), 24.0);
    EXPECT_EQ(info["clip"].get<std::string>(), "Armature|Walk");
    EXPECT_EQ(info["up_axis"].get<std::string>(), "y");
    EXPECT_EQ(info["time_range_s"][0].get<double>(), 0.25);
    EXPECT_EQ(info["time_range_s"][1].get<double>(), 0.25 + 7 / 24.0);
    const testing::CliResult text = testing::run_cli({"inspect", "run.h5"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("time: 0.25 s .. 0.541667 s at 24 fps, clip 'Armature|Walk', up axis y"), std::string::npos)
        << text.out;
    const testing::CliResult plain = testing::run_cli({"inspect", "plain.h5", "--json"}, dir.path());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    const auto plain_info = nlohmann::json::parse(plain.out);
    EXPECT_TRUE(plain_info["fps"].is_null());
    EXPECT_TRUE(plain_info["time_range_s"].is_null());
    EXPECT_EQ(testing::run_cli({"inspect", "plain.h5"}, dir.path()).out.find("time:"), std::string::npos);
}

// Runs Debian's python3 on `code` in `dir` with this repository's python/ and scripts/ on the
// path; returns its exit code and output.
std::pair<int, std::string> run_python(const std::string& code, const std::filesystem::path& dir) {
    std::ofstream(dir / "check.py") << code;
    const std::string source = COLLIDESCOPE_SOURCE_DIR;
    const std::string command = "cd '" + dir.string() + "' && MPLBACKEND=Agg PYTHONPATH='" + source + "/python:" + source +
                                "/scripts' /usr/bin/python3 check.py > check.out 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(dir / "check.out");
    std::stringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(FrameTimes, ThePythonReaderAndThePlotUseTheTimes) {
    TempDir dir;
    testing::record_in_process(timed_scene(24, 6), dir.path() / "run.h5", 1, 6, false);
    testing::record_in_process(testing::crossing_sheets(3, 3), dir.path() / "plain.h5", 0, 3, false);
    const auto [code, out] = run_python(R"(
import subprocess, sys
import collidescope
with collidescope.open("run.h5") as rec:
    assert list(rec.times) == [0.25 + k / 24.0 for k in range(1, 6)], rec.times
    assert list(rec.stats["time"]) == list(rec.times)
    assert rec.fps == 24.0 and rec.clip == "Armature|Walk" and rec.up_axis == "y", (rec.fps, rec.clip, rec.up_axis)
with collidescope.open("plain.h5") as rec:
    assert rec.times is None and rec.stats["time"] is None and rec.fps is None and rec.up_axis is None
import os
script = os.path.join(os.environ["PYTHONPATH"].split(":")[1], "recording_plot_times.py")
for name in ("run.h5", "plain.h5"):
    print(subprocess.run([sys.executable, script, name, "-o", name + ".png"], check=True, capture_output=True,
                         text=True).stdout.strip())
)",
                                        dir.path());
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("wrote run.h5.png (5 frames; x axis: time (s))"), std::string::npos) << out;
    EXPECT_NE(out.find("wrote plain.h5.png (3 frames; x axis: frame)"), std::string::npos) << out;
}

}  // namespace
}  // namespace collidescope
