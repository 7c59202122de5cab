// Round trips: what the engine reported comes back from the file exactly (through the tool's
// reader), equals `check --pairs` / `check --stats` on the same input, and reads the same
// through h5py.

#include "recording_helpers.hpp"

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/validate.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace collidescope {
namespace {

using testing_files::TempDir;

std::vector<std::string> stage_names() {
    std::vector<std::string> names;
    for_each_stage(StageTimes{}, [&](const char* name, double) { names.emplace_back(name); });
    return names;
}

// Every row of the recording equals what the engine reported for that frame.
void expect_recording_equals(const recorder::Recording& rec, const std::vector<testing::CapturedFrame>& frames) {
    ASSERT_EQ(rec.frames_complete(), frames.size());
    EXPECT_TRUE(rec.finished());
    const std::vector<std::uint32_t> indices = rec.frame_indices();
    const std::vector<std::string> methods = rec.frame_methods();
    const auto ms = rec.stage_ms();
    const auto counts = rec.counts();
    ASSERT_EQ(ms.size(), stage_names().size());
    for (std::size_t r = 0; r < frames.size(); ++r) {
        const testing::CapturedFrame& expected = frames[r];
        EXPECT_EQ(indices[r], expected.stats.frame);
        EXPECT_EQ(methods[r], expected.stats.method);
        EXPECT_EQ(rec.pairs(r), expected.pairs) << "frame row " << r;
        std::size_t s = 0;
        for_each_stage(expected.stats.ms, [&](const char* name, double value) {
            EXPECT_EQ(ms[s].name, name);
            EXPECT_EQ(ms[s].unit, "ms");
            EXPECT_EQ(ms[s].values[r], value) << name << " row " << r;  // float64 both ways: exact
            ++s;
        });
        std::size_t c = 0;
        for_each_count(expected.stats.counts, [&](const char* name, std::uint64_t value) {
            ASSERT_LT(c, counts.size());
            EXPECT_EQ(counts[c].name, name);
            EXPECT_EQ(counts[c].values[r], value) << name << " row " << r;
            ++c;
        });
        EXPECT_EQ(c, counts.size());
        for (std::uint32_t k = 0; k < expected.vertices.size(); ++k) {
            const std::vector<float> positions = rec.positions(k, r);
            ASSERT_EQ(positions.size(), expected.vertices[k].size() * 3) << "object " << k << " row " << r;
            for (std::size_t v = 0; v < expected.vertices[k].size(); ++v) {
                for (int axis = 0; axis < 3; ++axis) {
                    ASSERT_EQ(positions[3 * v + static_cast<std::size_t>(axis)], static_cast<float>(expected.vertices[k][v][axis]));
                }
            }
            EXPECT_EQ(rec.triangles(k, rec.topology_at(k, indices[r])), expected.triangles[k]);
        }
    }
}

TEST(RecorderRoundTrip, EveryFrameComesBackExactly) {
    TempDir dir;
    const Scene scene = make_builtin_scene("demo:small");
    const auto frames = testing::record_in_process(scene, dir.path() / "run.h5", 0, scene.source->frame_count(), false);
    const recorder::Recording rec(dir.path() / "run.h5");
    expect_recording_equals(rec, frames);
    std::uint64_t total_pairs = 0;
    for (const auto& frame : frames) total_pairs += frame.pairs.size();
    EXPECT_GT(total_pairs, 0u) << "the scene must collide somewhere, or pairs are not exercised";
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
}

TEST(RecorderRoundTrip, TopologyChangesAreRecordedFromTheirFrame) {
    TempDir dir;
    // Object 1 changes its triangles (and vertex count) at frame 3 and again at frame 5.
    std::vector<std::vector<MeshData>> meshes;
    for (std::uint32_t f = 0; f < 7; ++f) {
        const std::uint32_t cells = f < 3 ? 2 : (f < 5 ? 3 : 4);
        meshes.push_back({testing::grid_sheet(3, 1.0), testing::translated(testing::grid_sheet(cells, 1.0), Vec3(0.5, 0.1 * f, 0))});
    }
    Scene scene;
    scene.name = "topology";
    scene.source = make_memory_source({"fixed", "changing"}, std::move(meshes));
    // Start at frame 1: the first topology applies from the first recorded frame.
    const auto frames = testing::record_in_process(scene, dir.path() / "topo.h5", 1, 7, false);
    const recorder::Recording rec(dir.path() / "topo.h5");
    expect_recording_equals(rec, frames);
    ASSERT_EQ(rec.objects().size(), 2u);
    ASSERT_EQ(rec.objects()[0].topologies.size(), 1u);
    ASSERT_EQ(rec.objects()[1].topologies.size(), 3u);
    EXPECT_EQ(rec.objects()[1].topologies[0].from_frame, 1u);
    EXPECT_EQ(rec.objects()[1].topologies[1].from_frame, 3u);
    EXPECT_EQ(rec.objects()[1].topologies[2].from_frame, 5u);
    EXPECT_EQ(rec.objects()[1].topologies[2].triangle_count, 2u * 4 * 4);
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
}

// Positions chunks hold the first frame's vertices; a frame with another vertex count fills
// chunks partly, and the next frame rewrites the partial chunk whole (recording_writer.cpp). Vertex
// counts drawn at random, above and below the first frame's, come back exactly.
TEST(RecorderRoundTrip, PositionsOfEveryVertexCountComeBackExactly) {
    const std::uint64_t seed = 77;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    TempDir dir;
    const Scene scene = testing::varying_vertex_counts(seed, 40);
    const auto frames = testing::record_in_process(scene, dir.path() / "counts.h5", 0, 40, false);
    const recorder::Recording rec(dir.path() / "counts.h5");
    expect_recording_equals(rec, frames);
    EXPECT_TRUE(recorder::validate_recording(rec).problems.empty());
}

// `record` and `check` on the same input: the recorded pairs are check's TSV, the recorded
// counts check's stats; then h5py reads the same (tests/recorder/check_recording.py).
void expect_record_matches_check(const std::vector<std::string>& input, const TempDir& dir) {
    // brute: deterministic counts (adaptive, the default, and aabb's rebuild policy decide from
    // measured times).
    std::vector<std::string> record_args = {"record", "-o", "run.h5", "-q", "--method", "brute"};
    record_args.insert(record_args.end(), input.begin(), input.end());
    const testing::CliResult recorded = testing::run_cli(record_args, dir.path());
    ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
    std::vector<std::string> check_args = {"check", "--pairs", "pairs.tsv", "--stats", "stats.jsonl", "--exit-zero", "-q",
                                           "--method", "brute"};
    check_args.insert(check_args.end(), input.begin(), input.end());
    const testing::CliResult checked = testing::run_cli(check_args, dir.path());
    ASSERT_EQ(checked.exit_code, 0) << checked.err;

    const recorder::Recording rec(dir.path() / "run.h5");
    std::vector<testing::FramePair> from_file;
    const std::vector<std::uint32_t> indices = rec.frame_indices();
    for (std::uint64_t r = 0; r < rec.frames_complete(); ++r) {
        for (const TrianglePair& pair : rec.pairs(r)) from_file.push_back({indices[r], pair});
    }
    const auto from_check = testing::parse_pairs_tsv(testing::read_text(dir.path() / "pairs.tsv"));
    EXPECT_FALSE(from_check.empty());
    EXPECT_EQ(from_file, from_check);

    std::istringstream stats(testing::read_text(dir.path() / "stats.jsonl"));
    const auto counts = rec.counts();
    const auto methods = rec.frame_methods();
    std::uint64_t row = 0;
    for (std::string line; std::getline(stats, line); ++row) {
        const nlohmann::json json = nlohmann::json::parse(line);
        ASSERT_LT(row, rec.frames_complete());
        EXPECT_EQ(json["frame"].get<std::uint32_t>(), indices[row]);
        EXPECT_EQ(json["method"].get<std::string>(), methods[row]);
        for (const auto& series : counts) EXPECT_EQ(json["counts"][series.name].get<std::uint64_t>(), series.values[row]) << series.name;
    }
    EXPECT_EQ(row, rec.frames_complete());

    const std::string script = std::string(COLLIDESCOPE_SOURCE_DIR) + "/tests/recorder/check_recording.py";
    const std::string command = "/usr/bin/python3 '" + script + "' '" + (dir.path() / "run.h5").string() + "' '" +
                                (dir.path() / "pairs.tsv").string() + "' '" + (dir.path() / "stats.jsonl").string() +
                                "' > '" + (dir.path() / "py.out").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_EQ(status, 0) << testing::read_text(dir.path() / "py.out");
}

TEST(RecorderRoundTrip, RecordMatchesCheckAndH5py) {
    TempDir dir;
    expect_record_matches_check({"--scene", "demo:small"}, dir);
}

TEST(RecorderRoundTrip, RecordMatchesCheckWithSelfCollisionAndAFrameRange) {
    TempDir dir;
    expect_record_matches_check({"--scene", "C:small", "--self", "--frames", "3:11"}, dir);
}

TEST(RecorderRoundTrip, RecordMatchesCheckOnFrameFiles) {
    TempDir dir;
    const std::vector<std::string> patterns = testing::write_scene_files(testing::crossing_sheets(6, 12), dir.path());
    expect_record_matches_check(patterns, dir);
}

}  // namespace
}  // namespace collidescope
