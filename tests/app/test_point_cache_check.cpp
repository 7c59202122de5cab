// `collidescope check` on meshes with point caches (PC2, MDD; `mesh@cache` and scene.json)
// gives exactly the pairs of the same motion written as PLY frame sequences, which are the
// brute-force reference's pairs; the motion (the demo scene: a spinning torus and a waving
// sheet through it) has real contacts, so the comparison is not between empty lists.

#include "mesh/temp_files.hpp"
#include "support/cli_runner.hpp"
#include "support/point_cache_writer.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing::FramePair;
using testing::PositionFrames;
using testing_files::TempDir;
using testing_files::write_text;

// Writes object `object` of `scene` as MESH.ply (frame 0) and its frames as positions.
PositionFrames write_mesh_and_frames(const Scene& scene, std::uint32_t object, const std::filesystem::path& mesh) {
    PositionFrames frames;
    MeshData first;
    for (const Frame& frame : testing::all_frames(scene)) {
        frames.push_back(frame.objects[object].vertices.to_vector());
        if (frame.index == 0) first.triangles = frame.objects[object].topology->triangles;
    }
    first.vertices = frames.front();
    write_ply(mesh, first);
    return frames;
}

std::vector<FramePair> check_pairs(const std::vector<std::string>& inputs, const std::filesystem::path& dir,
                                   bool self) {
    std::vector<std::string> args = {"check", "--quiet", "--exit-zero", "--pairs", "pairs.tsv"};
    if (self) args.push_back("--self");
    args.insert(args.end(), inputs.begin(), inputs.end());
    const testing::CliResult result = testing::run_cli(args, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return testing::parse_pairs_tsv(testing::read_text(dir / "pairs.tsv"));
}

TEST(PointCacheCheck, CachesGiveTheSequencesPairs) {
    TempDir dir;
    const Scene demo = make_builtin_scene("demo:small");
    const std::vector<std::string> patterns = testing::write_scene_files(demo, dir.path());
    const PositionFrames torus = write_mesh_and_frames(demo, 0, dir / "torus.ply");
    const PositionFrames sheet = write_mesh_and_frames(demo, 1, dir / "sheet.ply");
    testing::write_pc2(dir / "torus.pc2", torus);
    testing::write_mdd(dir / "torus.mdd", torus, std::vector<float>(torus.size(), 0.0f));
    testing::write_pc2(dir / "sheet.pc2", sheet, 1.0f, 0.5f);
    std::vector<float> times;
    for (std::size_t k = 0; k < sheet.size(); ++k) times.push_back(static_cast<float>(k) / 25.0f);
    testing::write_mdd(dir / "sheet.mdd", sheet, times);
    write_text(dir / "scene.json", R"({"objects": [{"mesh": "torus.ply", "cache": "torus.mdd"},
                                                   {"mesh": "sheet.ply", "cache": "sheet.pc2"}]})");

    for (const bool self : {false, true}) {
        SCOPED_TRACE(self ? "with --self" : "without --self");
        const std::vector<FramePair> sequence = check_pairs(patterns, dir.path(), self);
        // The PLY files hold float32 coordinates: the reference runs on the files as read.
        EXPECT_EQ(sequence, testing::reference_frame_pairs(open_inputs(patterns), self));
        ASSERT_GT(sequence.size(), 10u) << "the motion must have contacts";
        EXPECT_EQ(check_pairs({"torus.ply@torus.pc2", "sheet.ply@sheet.mdd"}, dir.path(), self), sequence);
        EXPECT_EQ(check_pairs({"torus.ply@torus.mdd", "sheet.ply@sheet.pc2"}, dir.path(), self), sequence);
        EXPECT_EQ(check_pairs({"scene.json"}, dir.path(), self), sequence);
    }
}

TEST(PointCacheCheck, FramesSelectAmongTheCachesFrames) {
    TempDir dir;
    const Scene demo = make_builtin_scene("demo:small");
    const std::vector<std::string> patterns = testing::write_scene_files(demo, dir.path());
    testing::write_pc2(dir / "torus.pc2", write_mesh_and_frames(demo, 0, dir / "torus.ply"));
    testing::write_pc2(dir / "sheet.pc2", write_mesh_and_frames(demo, 1, dir / "sheet.ply"));
    std::vector<std::string> sequence_args = patterns;
    sequence_args.insert(sequence_args.end(), {"--frames", "5:15"});
    std::vector<std::string> cache_args = {"torus.ply@torus.pc2", "sheet.ply@sheet.pc2", "--frames", "5:15"};
    const std::vector<FramePair> sequence = check_pairs(sequence_args, dir.path(), false);
    ASSERT_FALSE(sequence.empty());
    EXPECT_EQ(check_pairs(cache_args, dir.path(), false), sequence);
}

}  // namespace
}  // namespace collidescope
