// Packed doubles reach the engine without a copy: the frame's vertices point at the caller's
// buffer (take_vertices), and a step reports counts.positions_copied_bytes = 0 for them and
// V * 24 for the layouts it converts. Nothing reads the caller's buffer after the step: the
// recording holds what was passed even when the buffer is overwritten right after each step.

#include "session_helpers.hpp"

#include "frame_input.hpp"
#include "mesh/temp_files.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace collidescope {
namespace {

using testing::Layout;
using testing_files::TempDir;

std::vector<double> some_xyz(std::size_t count) {
    std::vector<double> xyz(3 * count);
    for (std::size_t i = 0; i < xyz.size(); ++i) xyz[i] = 0.25 * static_cast<double>(i % 17) - 1.0;
    return xyz;
}

TEST(ZeroCopy, PackedDoublesAreViewedWhereTheyLie) {
    const std::vector<double> xyz = some_xyz(50);
    std::vector<Vec3> converted;
    FrameVertices vertices;
    EXPECT_EQ(api::take_vertices(vertex_view(std::span<const double>(xyz)), converted, vertices, "object 0"), 0u);
    EXPECT_FALSE(vertices.owns());
    EXPECT_EQ(static_cast<const void*>(vertices.data()), static_cast<const void*>(xyz.data()))
        << "the engine's frame reads the caller's buffer itself";
    EXPECT_EQ(vertices.size(), 50u);
    EXPECT_TRUE(converted.empty()) << "nothing was converted";
    // One vertex: any row stride is packed.
    EXPECT_EQ(api::take_vertices(vertex_view(xyz.data(), 1, 5 * sizeof(double)), converted, vertices, "object 0"), 0u);
    EXPECT_EQ(static_cast<const void*>(vertices.data()), static_cast<const void*>(xyz.data()));
}

// The converting layouts (float32, strided, packed doubles off a double's alignment) give the
// same doubles as the slow one-coordinate-at-a-time reference, 24 bytes per vertex.
TEST(ZeroCopy, OtherLayoutsAreConvertedOnce) {
    const std::vector<double> xyz = some_xyz(40);
    const std::vector<float> floats(xyz.begin(), xyz.end());
    std::vector<double> padded(4 * 40 + 1, 0.0);
    for (std::size_t v = 0; v < 40; ++v) std::copy_n(xyz.begin() + 3 * v, 3, padded.begin() + 4 * v);
    std::vector<unsigned char> bytes(xyz.size() * sizeof(double) + 1);
    std::memcpy(bytes.data() + 1, xyz.data(), xyz.size() * sizeof(double));
    const VertexView views[] = {vertex_view(std::span<const float>(floats)), vertex_view(padded.data(), 40, 4 * sizeof(double)),
                                VertexView{bytes.data() + 1, 40, Scalar::Float64, 3 * sizeof(double), sizeof(double)}};
    for (const VertexView& view : views) {
        EXPECT_FALSE(api::viewable_in_place(view));
        std::vector<Vec3> converted;
        FrameVertices vertices;
        EXPECT_EQ(api::take_vertices(view, converted, vertices, "object 0"), 40u * 24u);
        EXPECT_EQ(vertices.data(), converted.data());
        std::vector<Vec3> reference;
        api::copy_vertices_reference(view, reference, "object 0");
        EXPECT_TRUE(vertices == FrameVertices(reference));
    }
}

// The finiteness check still reads every coordinate of a view in place.
TEST(ZeroCopy, NonFiniteCoordinatesInAViewAreNamed) {
    std::vector<double> xyz = some_xyz(30);
    xyz[3 * 11 + 1] = std::nan("");
    std::vector<Vec3> converted;
    FrameVertices vertices;
    try {
        api::take_vertices(vertex_view(std::span<const double>(xyz)), converted, vertices, "object 3 ('lid')");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "object 3 ('lid'): vertex 11 has a non-finite y coordinate (nan)");
    }
}

// A session with one object in each layout: the stat counts the converted object only, and
// `check --stats`' JSON carries it under counts.
TEST(ZeroCopy, StepStatsCountTheConvertedBytes) {
    SceneFrames scene = SceneFrames::builtin("C:small");
    Session session({.method = "aabb"});
    testing::declare_objects(session, scene);
    scene.load(3);
    const testing::CallerPositions packed(scene.positions(0), Layout::Packed);
    const testing::CallerPositions single(scene.positions(1), Layout::Float32);
    const VertexView views[] = {packed.view, single.view};
    const std::size_t pairs = session.step(views).size();
    const std::uint64_t expected = single.view.count * 24;
    EXPECT_EQ(session.stats().counts.positions_copied_bytes, expected);
    EXPECT_NE(session.stats_json().find("\"positions_copied_bytes\":" + std::to_string(expected)), std::string::npos)
        << session.stats_json();

    Session in_place({.method = "aabb"});
    testing::declare_objects(in_place, scene);
    scene.load(3);
    const testing::CallerPositions other(scene.positions(1), Layout::Packed);
    const VertexView doubles[] = {packed.view, other.view};
    EXPECT_EQ(in_place.step(doubles).size(), pairs);
    EXPECT_EQ(in_place.stats().counts.positions_copied_bytes, 0u);
}

// A NaN thrown from a view leaves the session usable; the next step's pairs are the reference's.
TEST(ZeroCopy, ASessionStaysUsableAfterABadView) {
    SceneFrames scene = SceneFrames::builtin("C:small");
    Session session({.method = "aabb"});
    testing::declare_objects(session, scene);
    scene.load(4);
    testing::CallerPositions a(scene.positions(0), Layout::Packed);
    testing::CallerPositions b(scene.positions(1), Layout::Packed);
    b.doubles[7] = std::nan("");
    const VertexView bad[] = {a.view, b.view};
    EXPECT_THROW(session.step(bad), InputError);
    b.doubles[7] = scene.positions(1)[7];
    const std::size_t pairs = session.step(bad).size();
    Session fresh({.method = "aabb"});
    testing::declare_objects(fresh, scene);
    scene.load(4);
    const VertexView good[] = {vertex_view(scene.positions(0)), vertex_view(scene.positions(1))};
    EXPECT_EQ(fresh.step(good).size(), pairs);
}

// The recorder copies the positions during the step (its writer thread runs later): a caller
// that overwrites its buffers right after every step still finds each frame's positions in
// the file. Method adaptive, so the background rebuild (which keeps positions across frames)
// runs too, and its pairs are check's.
TEST(ZeroCopy, RecordingHoldsThePositionsPassedNotTheBuffersLater) {
    const TempDir dir;
    const std::string path = (dir / "run.h5").string();
    SceneFrames scene = SceneFrames::builtin("D:small");
    std::vector<testing::FramePair> stepped;
    {
        Session session({.method = "adaptive", .self_collision = scene.self_collision(), .record = path});
        testing::declare_objects(session, scene);
        stepped = testing::session_pairs(session, scene, Layout::Packed);  // poisons each buffer after its step
        session.close();
    }
    const testing::CliResult check = testing::run_cli(
        {"check", "--scene", "D:small", "--method", "adaptive", "--pairs", "-", "--exit-zero", "-q"}, dir.path());
    ASSERT_EQ(check.exit_code, 0) << check.err;
    EXPECT_TRUE(stepped == testing::parse_pairs_tsv(check.out));

    const recorder::Recording recording(path);
    ASSERT_EQ(recording.frames_complete(), scene.frame_count());
    for (std::uint32_t f = 0; f < scene.frame_count(); ++f) {
        scene.load(f);
        for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
            const std::vector<float> positions = recording.positions(k, f);
            const std::span<const double> expected = scene.positions(k);
            ASSERT_EQ(positions.size(), expected.size()) << "frame " << f << " object " << k;
            for (std::size_t i = 0; i < positions.size(); ++i) {
                ASSERT_EQ(positions[i], static_cast<float>(expected[i])) << "frame " << f << " object " << k << " " << i;
            }
        }
    }
}

}  // namespace
}  // namespace collidescope
