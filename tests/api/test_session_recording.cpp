// A session's recording is the file `collidescope record` writes: `validate` accepts it,
// `inspect` reads it, and its pairs and positions are the session's, frame by frame.

#include "session_helpers.hpp"

#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing_files::TempDir;

TEST(SessionRecording, IsAValidRecordingOfTheSessionsFrames) {
    const TempDir dir;
    const std::string path = (dir / "run.h5").string();
    SceneFrames scene = SceneFrames::builtin("C:small");
    std::vector<testing::FramePair> stepped;
    {
        Session session({.method = "aabb", .record = path, .scene = "sheets"});
        testing::declare_objects(session, scene);
        stepped = testing::session_pairs(session, scene);
        session.close();
    }
    ASSERT_FALSE(stepped.empty());
    const testing::CliResult validate = testing::run_cli({"validate", "run.h5"}, dir.path());
    EXPECT_EQ(validate.exit_code, 0) << validate.out << validate.err;
    const testing::CliResult inspect = testing::run_cli({"inspect", "run.h5"}, dir.path());
    EXPECT_EQ(inspect.exit_code, 0) << inspect.err;
    EXPECT_NE(inspect.out.find("sheets"), std::string::npos) << inspect.out;

    const recorder::Recording recording(path);
    EXPECT_TRUE(recording.finished());
    ASSERT_EQ(recording.frames_complete(), scene.frame_count());
    ASSERT_EQ(recording.objects().size(), 2u);
    EXPECT_EQ(recording.objects()[0].name, scene.object_name(0));
    std::vector<testing::FramePair> recorded;
    for (std::uint32_t row = 0; row < recording.frames_complete(); ++row) {
        EXPECT_EQ(recording.frame_indices()[row], row);
        for (const TrianglePair& pair : recording.pairs(row)) recorded.push_back({row, pair});
    }
    EXPECT_TRUE(recorded == stepped);
    // Positions are recorded as float32: those of the last frame, rounded.
    scene.load(scene.frame_count() - 1);
    const std::vector<float> positions = recording.positions(1, scene.frame_count() - 1);
    const std::span<const double> expected = scene.positions(1);
    ASSERT_EQ(positions.size(), expected.size());
    for (std::size_t i = 0; i < positions.size(); ++i) ASSERT_EQ(positions[i], static_cast<float>(expected[i])) << i;
}

TEST(SessionRecording, AnUncreatableFileIsNamed) {
    Session session({.record = "/nonexistent-directory/run.h5"});
    const std::array<std::uint32_t, 3> triangle[] = {{0, 1, 2}};
    session.add_object(triangle);
    const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const VertexView views[] = {vertex_view(std::span<const double>(xyz))};
    try {
        session.step(views);
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/nonexistent-directory/run.h5"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace collidescope
