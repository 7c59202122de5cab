// The facade's pairs are the engine's: a Session stepped through every built-in data set
// (small presets) reports exactly `collidescope check --pairs`, for the default method and
// the brute-force oracle, from packed doubles the engine views in place and from float32 and
// strided positions it converts; and on random scenes exactly the brute-force reference.

#include "session_helpers.hpp"

#include "mesh/temp_files.hpp"
#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing::FramePair;
using testing_files::TempDir;

using testing::Layout;

struct Case {
    const char* scene;
    const char* method;
    Layout layout = Layout::Packed;
};

class SessionEqualsCheck : public ::testing::TestWithParam<Case> {};

std::string case_name(const ::testing::TestParamInfo<Case>& test) {
    static const char* const layouts[] = {"", "_float32", "_padded"};
    std::string name = std::string(test.param.scene) + "_" + test.param.method + layouts[static_cast<int>(test.param.layout)];
    for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    return name;
}

TEST_P(SessionEqualsCheck, EveryFrame) {
    const Case c = GetParam();
    SceneFrames scene = SceneFrames::builtin(c.scene);
    Session session({.method = c.method, .self_collision = scene.self_collision()});
    testing::declare_objects(session, scene);
    const std::vector<FramePair> ours = testing::session_pairs(session, scene, c.layout);

    const TempDir dir;
    const testing::CliResult check =
        testing::run_cli({"check", "--scene", c.scene, "--method", c.method, "--pairs", "-", "--exit-zero", "-q"}, dir.path());
    ASSERT_EQ(check.exit_code, 0) << check.err;
    const std::vector<FramePair> expected = testing::parse_pairs_tsv(check.out);
    ASSERT_FALSE(expected.empty()) << c.scene << ": a data set without collisions tests nothing";
    EXPECT_EQ(ours.size(), expected.size());
    EXPECT_TRUE(ours == expected) << c.scene << " " << c.method << ": the session's pairs differ from check's";
    EXPECT_EQ(session.frame_count(), scene.frame_count());
}

INSTANTIATE_TEST_SUITE_P(DataSets, SessionEqualsCheck,
    ::testing::Values(Case{"A:small", "adaptive"}, Case{"B:small", "adaptive"}, Case{"C:small", "adaptive"},
                      Case{"D:small", "adaptive"}, Case{"E1:small", "adaptive"}, Case{"E2:small", "adaptive"},
                      Case{"E3:small", "adaptive"}, Case{"E4:small", "adaptive"}, Case{"demo:small", "adaptive"},
                      Case{"C:small", "aabb"}, Case{"B:small", "brute"},
                      // The converting paths against the same oracle (the fast path above).
                      Case{"C:small", "aabb", Layout::Float32}, Case{"C:small", "aabb", Layout::Padded},
                      Case{"D:small", "adaptive", Layout::Float32}, Case{"E2:small", "adaptive", Layout::Padded}),
    case_name);

// Random scenes of soups and crumpled sheets (touching, coplanar, degenerate triangles), self
// collision on and off: every frame's pairs equal the brute-force reference.
TEST(SessionPairs, RandomScenesEqualTheReference) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const bool self = seed % 2 == 0;
        const Scene scene = testing::random_scene(seed, {.objects = 3, .frames = 3});
        const std::vector<Frame> frames = testing::all_frames(scene);
        Session session({.method = "aabb", .self_collision = self});
        for (const ObjectFrame& object : frames[0].objects) session.add_object(object.topology->triangles);
        std::size_t total = 0;
        for (const Frame& frame : frames) {
            std::vector<VertexView> views;
            for (const ObjectFrame& object : frame.objects) views.push_back(vertex_view(object.vertices.front().data(), object.vertices.size()));
            const std::span<const CollidingPair> pairs = session.step(views);
            const std::vector<TrianglePair> expected = testing::reference_colliding_pairs(frame, self);
            ASSERT_EQ(pairs.size(), expected.size()) << "seed " << seed << " frame " << frame.index;
            for (std::size_t i = 0; i < pairs.size(); ++i) {
                const TrianglePair got{pairs[i].obj_a, pairs[i].tri_a, pairs[i].obj_b, pairs[i].tri_b};
                ASSERT_EQ(got, expected[i]) << "seed " << seed << " frame " << frame.index << " pair " << i;
            }
            total += pairs.size();
        }
        EXPECT_GT(total, 0u) << "seed " << seed << ": no collisions, nothing tested";
    }
}

// The stats are those of check --stats: the same JSON names, and counts that agree with the pairs.
TEST(SessionPairs, StatsMatchThePairs) {
    SceneFrames scene = SceneFrames::builtin("C:small");
    Session session({.method = "aabb"});
    testing::declare_objects(session, scene);
    scene.load(5);
    const VertexView views[] = {vertex_view(scene.positions(0)), vertex_view(scene.positions(1))};
    const std::size_t pairs = session.step(views).size();
    EXPECT_EQ(session.stats().counts.colliding_pairs, pairs);
    EXPECT_EQ(session.stats().frame, 0u);
    EXPECT_EQ(session.stats().method, "aabb");
    EXPECT_GT(session.stats().ms.total, 0.0);
    const std::string json = session.stats_json();
    EXPECT_EQ(json.rfind("{\"frame\":0,\"method\":\"aabb\",\"ms\":{\"update\":", 0), 0u) << json;
    EXPECT_NE(json.find("\"colliding_pairs\":" + std::to_string(pairs)), std::string::npos) << json;
}

}  // namespace
}  // namespace collidescope
