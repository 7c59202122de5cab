// `join`: recordings of contiguous frame ranges joined into one equal the recording of the
// whole range (every dataset's rows, pairs, positions, topologies, counts), whatever the order
// the parts are given in and wherever their boundaries fall in the chunks; mismatched parts
// (overlap, gap, another scene, an unfinished part) are refused with one line naming them and
// leave no output behind.

#include "join_helpers.hpp"
#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/join.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

namespace fs = std::filesystem;
using recorder::Recording;
using testing::expect_same_recording;
using testing_files::TempDir;

// Records `scene` whole and in the parts `bounds` gives, joins the parts (listed last first).
void check_join(const Scene& scene, const std::vector<std::uint32_t>& bounds, const std::string& method,
                std::uint64_t* raw_chunks = nullptr) {
    TempDir dir;
    testing::record_in_process(scene, dir / "whole.h5", bounds.front(), bounds.back(), false, method);
    std::vector<fs::path> parts;
    for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
        const fs::path part = dir / ("part" + std::to_string(i) + ".h5");
        testing::record_in_process(scene, part, bounds[i], bounds[i + 1], false, method);
        parts.insert(parts.begin(), part);
    }
    const recorder::JoinSummary summary = recorder::join_recordings(parts, dir / "joined.h5");
    EXPECT_EQ(summary.parts, parts.size());
    EXPECT_EQ(summary.frames, bounds.back() - bounds.front());
    EXPECT_TRUE(summary.complete);
    EXPECT_FALSE(fs::exists(dir / "joined.h5.partial"));
    if (raw_chunks != nullptr) *raw_chunks = summary.raw_chunks;
    expect_same_recording(Recording(dir / "joined.h5"), Recording(dir / "whole.h5"), method == "brute");
}

TEST(RecorderJoin, PartsOfConstantTopologyEqualTheWholeRecording) {
    // One positions chunk per frame: every part boundary is a chunk boundary, so positions go raw.
    const Scene scene = testing::crossing_sheets(6, 24);
    std::uint64_t raw = 0;
    check_join(scene, {0, 7, 8, 19, 24}, "aabb", &raw);
    EXPECT_GT(raw, 0u);
}

TEST(RecorderJoin, PartsWithChangingVertexCountsEqualTheWholeRecording) {
    // Vertex counts above and below the first frame's: part boundaries fall inside positions
    // chunks, and topologies change inside parts and at their boundaries.
    for (const std::uint64_t seed : {25u, 26u, 27u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        check_join(testing::varying_vertex_counts(seed, 30), {0, 11, 12, 20, 30}, "brute");
    }
}

TEST(RecorderJoin, OnePartIsACopy) {
    check_join(testing::crossing_sheets(4, 10), {0, 10}, "brute");
}

class JoinRefusal : public ::testing::Test {
protected:
    void SetUp() override {
        const Scene scene = testing::crossing_sheets(4, 20);
        testing::record_in_process(scene, m_dir / "a.h5", 0, 8, false);
        testing::record_in_process(scene, m_dir / "b.h5", 8, 20, false);
        testing::record_in_process(scene, m_dir / "overlap.h5", 6, 12, false);
        testing::record_in_process(scene, m_dir / "late.h5", 10, 20, false);
        testing::record_in_process(testing::varying_vertex_counts(25, 20), m_dir / "other.h5", 8, 20, false);
    }

    // The join fails with a message naming `named`; no output and no .partial are left.
    void expect_refused(const std::vector<std::string>& parts, const std::vector<std::string>& named,
                        recorder::JoinOptions options = {}) {
        std::vector<fs::path> paths;
        for (const std::string& part : parts) paths.push_back(m_dir / part);
        try {
            recorder::join_recordings(paths, m_dir / "out.h5", options);
            ADD_FAILURE() << "joined";
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            for (const std::string& name : named) EXPECT_NE(message.find(name), std::string::npos) << message;
        }
        EXPECT_FALSE(fs::exists(m_dir / "out.h5"));
        EXPECT_FALSE(fs::exists(m_dir / "out.h5.partial"));
    }

    TempDir m_dir;
};

TEST_F(JoinRefusal, Overlap) { expect_refused({"a.h5", "overlap.h5"}, {"a.h5", "overlap.h5", "overlap"}); }
TEST_F(JoinRefusal, Gap) { expect_refused({"late.h5", "a.h5"}, {"a.h5", "late.h5", "gap", "8..9"}); }
TEST_F(JoinRefusal, AnotherScene) { expect_refused({"a.h5", "other.h5"}, {"a.h5", "other.h5"}); }
TEST_F(JoinRefusal, TheOutputIsAPart) {
    std::vector<fs::path> paths = {m_dir / "a.h5", m_dir / "b.h5"};
    EXPECT_THROW(recorder::join_recordings(paths, m_dir / "b.h5"), InputError);
    EXPECT_NO_THROW(Recording(m_dir / "b.h5"));
}
TEST_F(JoinRefusal, NotARecording) {
    testing::write_foreign_hdf5(m_dir / "foreign.h5");
    expect_refused({"a.h5", "foreign.h5"}, {"foreign.h5"});
}

TEST_F(JoinRefusal, UnfinishedPartOnlyWithAllowIncomplete) {
    testing::delete_attr(m_dir / "a.h5", "/", "finished");
    expect_refused({"a.h5", "b.h5"}, {"a.h5", "--allow-incomplete"});
    recorder::JoinOptions options;
    options.allow_incomplete = true;
    const recorder::JoinSummary summary = recorder::join_recordings({m_dir / "a.h5", m_dir / "b.h5"}, m_dir / "out.h5", options);
    EXPECT_FALSE(summary.complete);
    const Recording joined(m_dir / "out.h5");
    EXPECT_FALSE(joined.finished());  // like its part: validate --allow-incomplete
    EXPECT_EQ(joined.frames_complete(), 20u);
}

// The command line: join, then compare and validate accept the output as the whole run's.
TEST(RecorderJoin, CommandLineJoinComparesEqualToTheSerialRecording) {
    TempDir dir;
    const std::vector<std::string> record = {"record", "--scene", "C:small", "--method", "aabb", "--threads", "1", "-q"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = record;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    auto run = [&](const std::vector<std::string>& args) { return testing::run_cli(args, dir.path()); };
    ASSERT_EQ(run(with({"-o", "serial.h5"})).exit_code, 0);
    ASSERT_EQ(run(with({"--frames", ":5", "-o", "part-0.h5"})).exit_code, 0);
    ASSERT_EQ(run(with({"--frames", "5:9", "-o", "part-1.h5"})).exit_code, 0);
    ASSERT_EQ(run(with({"--frames", "9:", "-o", "part-2.h5"})).exit_code, 0);
    const testing::CliResult join = run({"join", "part-2.h5", "part-0.h5", "part-1.h5", "-o", "run.h5"});
    ASSERT_EQ(join.exit_code, 0) << join.err;
    EXPECT_NE(join.err.find("joined 3 parts"), std::string::npos) << join.err;
    const testing::CliResult compare = run({"compare", "serial.h5", "run.h5"});
    EXPECT_EQ(compare.exit_code, 0) << compare.out << compare.err;
    EXPECT_NE(compare.out.find("identical in every matched frame"), std::string::npos) << compare.out;
    const testing::CliResult validate = run({"validate", "run.h5"});
    EXPECT_EQ(validate.exit_code, 0) << validate.err;
    expect_same_recording(Recording(dir / "run.h5"), Recording(dir / "serial.h5"), false);

    const testing::CliResult gap = run({"join", "part-0.h5", "part-2.h5", "-o", "gap.h5"});
    EXPECT_EQ(gap.exit_code, 2);
    ASSERT_EQ(gap.err_lines().size(), 1u) << gap.err;
    EXPECT_NE(gap.err.find("part-0.h5 and part-2.h5 leave a gap"), std::string::npos) << gap.err;
    EXPECT_FALSE(fs::exists(dir / "gap.h5"));
}

bool same_value(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void expect_same_series(const std::vector<recorder::Series<double>>& joined, const std::vector<recorder::Series<double>>& part,
                        std::uint64_t row, std::uint64_t part_row) {
    ASSERT_EQ(joined.size(), part.size());
    for (std::size_t s = 0; s < joined.size(); ++s) {
        EXPECT_TRUE(same_value(joined[s].values[row], part[s].values[part_row])) << joined[s].name << " row " << row;
    }
}

// The GPU cull's state (its view choices) makes a part's details differ from the whole run's,
// so here every row of the joined file, CSR-indexed tables included (passes, survivors, depth
// images with their nested pixel offsets), is checked against the row of the part it came from.
TEST(RecorderJoin, EveryRowOfTheGpuDetailsComesFromItsPart) {
    TempDir dir;
    const std::vector<std::string> record = {"record", "--scene", "C:small", "--method", "gpu", "--depth", "every:3",
                                             "--threads", "1", "-q", "-o"};
    auto run = [&](std::vector<std::string> args) { return testing::run_cli(args, dir.path()); };
    auto with = [&](const std::string& frames, const std::string& file) {
        std::vector<std::string> args = record;
        args.push_back(file);
        args.insert(args.end(), {"--frames", frames});
        return args;
    };
    ASSERT_EQ(run(with(":7", "p0.h5")).exit_code, 0);
    ASSERT_EQ(run(with("7:", "p1.h5")).exit_code, 0);
    ASSERT_EQ(run({"join", "p1.h5", "p0.h5", "-o", "joined.h5"}).exit_code, 0);
    EXPECT_EQ(run({"validate", "joined.h5"}).exit_code, 0);
    const Recording joined(dir / "joined.h5"), p0(dir / "p0.h5"), p1(dir / "p1.h5");
    const std::uint64_t n0 = p0.frames_complete();
    ASSERT_EQ(joined.frames_complete(), n0 + p1.frames_complete());
    std::uint64_t images = 0;
    for (std::uint64_t r = 0; r < joined.frames_complete(); ++r) {
        SCOPED_TRACE("row " + std::to_string(r));
        const Recording& part = r < n0 ? p0 : p1;
        const std::uint64_t pr = r < n0 ? r : r - n0;
        EXPECT_EQ(joined.pairs(r), part.pairs(pr));
        EXPECT_EQ(joined.survivors(r), part.survivors(pr));
        const auto passes = joined.gpu_passes(r), part_passes = part.gpu_passes(pr);
        ASSERT_EQ(passes.size(), part_passes.size());
        for (std::size_t i = 0; i < passes.size(); ++i) {
            EXPECT_EQ(passes[i].items_tested, part_passes[i].items_tested);
            EXPECT_EQ(passes[i].samples_passed, part_passes[i].samples_passed);
            EXPECT_EQ(passes[i].view, part_passes[i].view);
        }
        const auto depth = joined.depth_images(r), part_depth = part.depth_images(pr);
        ASSERT_EQ(depth.size(), part_depth.size());
        for (std::size_t i = 0; i < depth.size(); ++i) {
            EXPECT_EQ(depth[i].width, part_depth[i].width);
            EXPECT_EQ(depth[i].view, part_depth[i].view);
            EXPECT_EQ(depth[i].depth, part_depth[i].depth);
            EXPECT_EQ(depth[i].depth_near, part_depth[i].depth_near);
        }
        images += depth.size();
        expect_same_series(joined.frame_values("gpu"), part.frame_values("gpu"), r, pr);
        expect_same_series(joined.stage_ms(), part.stage_ms(), r, pr);
    }
    EXPECT_GT(images, 0u);
}

}  // namespace
}  // namespace collidescope
