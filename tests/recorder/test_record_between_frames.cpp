// record --between-frames: /intervals (schema 1.7) holds, interval by interval, what BetweenFrames
// gives on the same frames (pairs, times, flags and counts); validate checks it and names a
// broken offset or a frame pair missing from its interval; inspect sums it; a recording without
// the flag has none; a topology change is a one-line error naming the scene and object; join
// refuses parts with intervals.

#include "recording_helpers.hpp"
#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/datasets.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/recorder/validate.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing::run_cli;
using testing_files::TempDir;

// Records `scene` frames [begin, end) between frames and compares each interval with a fresh
// detector's on the scene's own frames.
void expect_intervals_equal_the_engines(const std::string& scene_name, std::uint32_t begin, std::uint32_t end, bool self) {
    TempDir dir;
    std::vector<std::string> args = {"record", "--scene", scene_name, "--frames", std::to_string(begin) + ":" + std::to_string(end),
                                     "--between-frames", "-o", "r.h5", "-q"};
    if (self) args.push_back("--self");
    const auto result = run_cli(args, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const recorder::Recording rec(dir.path() / "r.h5");
    ASSERT_TRUE(rec.has_intervals());
    EXPECT_EQ(rec.version_minor(), recorder::schema::k_version_minor);
    ASSERT_EQ(rec.frames_complete(), end - begin);

    Scene scene = make_builtin_scene(scene_name);
    BetweenFramesOptions options;
    options.self_collision = self;
    BetweenFrames detector(options);
    std::uint64_t pass_throughs = 0, pairs = 0;
    for (std::uint32_t f = begin; f + 1 < end; ++f) {
        SCOPED_TRACE(scene_name + " frames " + std::to_string(f) + "-" + std::to_string(f + 1));
        const IntervalResult expected = detector.detect(scene.source->frame(f), scene.source->frame(f + 1));
        const recorder::RecordedInterval got = rec.interval(f - begin + 1);
        EXPECT_EQ(got.from_frame, f);
        EXPECT_EQ(got.to_frame, f + 1);
        EXPECT_EQ(got.contacts, expected.contacts);
        EXPECT_EQ(got.stats.tolerance, expected.stats.tolerance);
        EXPECT_EQ(got.stats.candidate_pairs, expected.stats.candidate_pairs);
        EXPECT_EQ(got.stats.start_contacts, expected.stats.start_contacts);
        EXPECT_EQ(got.stats.primitive_queries, expected.stats.primitive_queries);
        EXPECT_EQ(got.stats.inclusion_boxes, expected.stats.inclusion_boxes);
        EXPECT_EQ(got.stats.contacts, expected.stats.contacts);
        EXPECT_EQ(got.stats.pass_throughs, expected.stats.pass_throughs);
        EXPECT_EQ(got.stats.unresolved, expected.stats.unresolved);
        EXPECT_GT(got.stats.ms, 0.0);
        pass_throughs += got.stats.pass_throughs;
        pairs += got.stats.contacts;
    }
    std::printf("%s frames %u:%u: %llu pairs between frames, %llu pass-throughs\n", scene_name.c_str(), begin, end,
                static_cast<unsigned long long>(pairs), static_cast<unsigned long long>(pass_throughs));
    EXPECT_GT(pass_throughs, 0u);
    const recorder::ValidationReport report = recorder::validate_recording(rec);
    EXPECT_TRUE(report.problems.empty()) << report.problems.front();
    const auto inspect = run_cli({"inspect", "r.h5"}, dir.path());
    EXPECT_NE(inspect.out.find("between frames: " + std::to_string(end - begin - 1) + " intervals"), std::string::npos)
        << inspect.out;
    EXPECT_NE(inspect.out.find(std::to_string(pass_throughs) + " pass-throughs"), std::string::npos) << inspect.out;
}

TEST(RecordBetweenFrames, IntervalsEqualTheEnginesTwoObjects) { expect_intervals_equal_the_engines("demo", 17, 23, false); }

TEST(RecordBetweenFrames, IntervalsEqualTheEnginesWithSelfContact) {
    expect_intervals_equal_the_engines("cloth-drape:small", 0, 6, true);
}

TEST(RecordBetweenFrames, ABrokenOffsetAndAMissingPairAreNamed) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "demo", "--frames", "17:23", "--between-frames", "-o", "r.h5", "-q"}, dir.path()).exit_code, 0);
    const std::filesystem::path file = dir.path() / "r.h5";
    {
        const recorder::Recording rec(file);
        ASSERT_GT(rec.interval(3).contacts.size(), 0u);
    }
    std::filesystem::copy_file(file, dir.path() / "short.h5");
    // Offsets past the pairs.
    testing::overwrite_u64(file, recorder::schema::k_interval_offsets, 2, 1u << 30);
    const recorder::ValidationReport report = recorder::validate_recording(recorder::Recording(file));
    ASSERT_FALSE(report.problems.empty());
    EXPECT_NE(report.problems.front().find("/intervals/offsets"), std::string::npos) << report.problems.front();
    EXPECT_NE(run_cli({"validate", "r.h5"}, dir.path()).exit_code, 0);
    // An interval that drops its pairs (its offsets say none) while a frame of it collides.
    std::uint64_t row = 0;
    std::vector<std::uint64_t> offsets;
    {
        const recorder::Recording before(dir.path() / "short.h5");
        for (std::uint64_t r = 1; r < before.frames_complete() && row == 0; ++r) {
            if (!before.pairs(r).empty()) row = r;
        }
        offsets = before.read_u64(recorder::schema::k_interval_offsets);
    }
    ASSERT_GT(row, 0u);
    for (std::uint64_t r = row + 1; r < offsets.size(); ++r) {
        testing::overwrite_u64(dir.path() / "short.h5", recorder::schema::k_interval_offsets, r,
                               offsets[r] - (offsets[row + 1] - offsets[row]));
    }
    const recorder::ValidationReport dropped = recorder::validate_recording(recorder::Recording(dir.path() / "short.h5"));
    ASSERT_FALSE(dropped.problems.empty());
    bool named = false;
    for (const std::string& line : dropped.problems) named = named || line.find("does not report it") != std::string::npos;
    EXPECT_TRUE(named) << dropped.problems.front();
}

TEST(RecordBetweenFrames, CorruptTimesAndFlagsAreNamedNotDrawnOrCrashed) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "demo", "--frames", "17:23", "--between-frames", "-o", "r.h5", "-q"}, dir.path()).exit_code, 0);
    std::filesystem::copy_file(dir.path() / "r.h5", dir.path() / "flags.h5");
    // A time of contact outside [0, 1]: inspect, validate and replay name /intervals/toi.
    testing::overwrite_f64(dir.path() / "r.h5", recorder::schema::k_interval_toi, 0, -5.0);
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"inspect", "r.h5"}, {"validate", "r.h5"}, {"replay", "r.h5", "-o", "out", "--contact-moments", "-q"}}) {
        const auto result = run_cli(command, dir.path());
        EXPECT_NE(result.exit_code, 0) << command[0];
        EXPECT_NE(result.err.find("/intervals/toi"), std::string::npos) << command[0] << ": " << result.err;
    }
    // Counts that say pass-throughs where the flags hold none: a one-line error, not a crash.
    std::uint64_t row = 0;
    std::vector<std::uint64_t> offsets;
    {
        const recorder::Recording rec(dir.path() / "flags.h5");
        for (std::uint64_t r = 1; r < rec.frames_complete() && row == 0; ++r) {
            if (rec.interval(r, false).stats.pass_throughs > 0) row = r;
        }
        offsets = rec.read_u64(recorder::schema::k_interval_offsets);
    }
    ASSERT_GT(row, 0u);
    for (std::uint64_t k = offsets[row]; k < offsets[row + 1]; ++k) {
        testing::overwrite_u64(dir.path() / "flags.h5", recorder::schema::k_interval_flags, k, 0);
    }
    const auto inspect = run_cli({"inspect", "flags.h5"}, dir.path());
    EXPECT_EQ(inspect.exit_code, 2) << inspect.err;
    EXPECT_NE(inspect.err.find("/intervals/flags"), std::string::npos) << inspect.err;
    EXPECT_EQ(std::count(inspect.err.begin(), inspect.err.end(), '\n'), 1) << inspect.err;
    const auto validate = run_cli({"validate", "flags.h5"}, dir.path());
    EXPECT_EQ(validate.exit_code, 1) << validate.err;
    EXPECT_NE(validate.err.find("pass-throughs"), std::string::npos) << validate.err;
}

TEST(RecordBetweenFrames, OnlyWithTheFlagErrorsNamedAndNeverJoined) {
    TempDir dir;
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "0:4", "-o", "plain.h5", "-q"}, dir.path()).exit_code, 0);
    EXPECT_FALSE(recorder::Recording(dir.path() / "plain.h5").has_intervals());
    const auto inspect = run_cli({"inspect", "plain.h5"}, dir.path());
    EXPECT_EQ(inspect.out.find("between frames"), std::string::npos);
    // D's mesh changes at frame 100: one line naming the scene, the object and the frames.
    const auto changed = run_cli({"record", "--scene", "D", "--frames", "99:101", "--between-frames", "-o", "d.h5", "-q"},
                                 dir.path());
    EXPECT_EQ(changed.exit_code, 2);
    EXPECT_NE(changed.err.find("scene 'D'"), std::string::npos) << changed.err;
    EXPECT_NE(changed.err.find("changes its mesh between frames 99 and 100"), std::string::npos) << changed.err;
    EXPECT_EQ(std::count(changed.err.begin(), changed.err.end(), '\n'), 1) << changed.err;
    const auto alone = run_cli({"record", "--scene", "C:small", "--ccd-tolerance", "0.1", "-o", "n.h5"}, dir.path());
    EXPECT_EQ(alone.exit_code, 2);
    EXPECT_NE(alone.err.find("--between-frames"), std::string::npos) << alone.err;
    const auto negative = run_cli({"record", "--scene", "C:small", "--between-frames", "--ccd-tolerance", "-1", "-o", "n.h5"},
                                  dir.path());
    EXPECT_EQ(negative.exit_code, 2);
    EXPECT_NE(negative.err.find("--ccd-tolerance"), std::string::npos) << negative.err;
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "0:4", "--between-frames", "-o", "a.h5", "-q"}, dir.path()).exit_code, 0);
    ASSERT_EQ(run_cli({"record", "--scene", "C:small", "--frames", "4:8", "--between-frames", "-o", "b.h5", "-q"}, dir.path()).exit_code, 0);
    const auto join = run_cli({"join", "a.h5", "b.h5", "-o", "joined.h5"}, dir.path());
    EXPECT_EQ(join.exit_code, 2);
    EXPECT_NE(join.err.find("holds /intervals"), std::string::npos) << join.err;
}

}  // namespace
}  // namespace collidescope
