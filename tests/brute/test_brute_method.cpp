// The brute method against the all-pairs reference (tests/support/brute_reference), and the
// details of its prefilter and counts.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "stages/object_level.hpp"

#include "collidescope/geometry.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace collidescope {
namespace {

using testing::make_frame;
using testing::reference_colliding_pairs;

std::vector<ObjectPair> all_object_pairs(const Frame& frame, bool self_collision) {
    std::vector<ObjectPair> pairs;
    const auto objects = static_cast<std::uint32_t>(frame.objects.size());
    for (std::uint32_t a = 0; a < objects; ++a) {
        for (std::uint32_t b = self_collision ? a : a + 1; b < objects; ++b) pairs.push_back({a, b});
    }
    return pairs;
}

struct BruteRun {
    std::vector<TrianglePair> pairs;  ///< sorted
    FrameStats stats;
};

// Runs the brute method alone (no object level: the given object pairs, default all).
BruteRun run_brute(const Frame& frame, bool self_collision, std::vector<ObjectPair> object_pairs) {
    const std::unique_ptr<Method> method = make_method("brute");
    const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
    const FrameContext context{frame, boxes, object_pairs, self_collision};
    BruteRun run;
    method->detect(context, run.pairs, run.stats);
    std::sort(run.pairs.begin(), run.pairs.end());
    return run;
}

BruteRun run_brute(const Frame& frame, bool self_collision) {
    return run_brute(frame, self_collision, all_object_pairs(frame, self_collision));
}

bool shares_vertex(const Frame& frame, const TrianglePair& pair) {
    if (pair.obj_a != pair.obj_b) return false;
    const TriIndices& a = frame.objects[pair.obj_a].topology->triangles[pair.tri_a];
    const TriIndices& b = frame.objects[pair.obj_b].topology->triangles[pair.tri_b];
    return std::any_of(a.begin(), a.end(), [&](std::uint32_t v) { return std::find(b.begin(), b.end(), v) != b.end(); });
}

// Triangles 0 and 1 share the edge (0, 1) and triangle 1 folds back over triangle 0;
// triangle 2 shares vertex 2 with triangle 0 and pierces it elsewhere.
MeshData folded_mesh() {
    MeshData mesh;
    mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, 1, 0}, {1, 1, -1}, {1.5, 0.5, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 1, 3}, {2, 4, 5}};
    return mesh;
}

TEST(BruteMethod, MatchesReferenceOnRandomScenes) {
    FrameCounts total;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        for (const Frame& frame : testing::all_frames(testing::random_scene(seed))) {
            const BruteRun run = run_brute(frame, false);
            ASSERT_EQ(run.pairs, reference_colliding_pairs(frame, false)) << "frame " << frame.index;
            total.box_tests += run.stats.counts.box_tests;
            total.candidate_pairs += run.stats.counts.candidate_pairs;
            total.colliding_pairs += run.stats.counts.colliding_pairs;
        }
    }
    // Both outcomes exercised at both stages: the prefilter removes pairs and lets through
    // pairs that the exact test then rejects, and pairs do collide.
    EXPECT_GT(total.colliding_pairs, 100u);
    EXPECT_LT(total.colliding_pairs, total.candidate_pairs);
    EXPECT_LT(total.candidate_pairs, total.box_tests);
}

TEST(BruteMethod, MatchesReferenceWithSelfCollision) {
    std::uint64_t adjacent_colliding = 0;
    std::uint64_t all_candidates = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        for (const Frame& frame : testing::all_frames(testing::random_scene(seed))) {
            const BruteRun run = run_brute(frame, true);
            ASSERT_EQ(run.pairs, reference_colliding_pairs(frame, true)) << "frame " << frame.index;
            adjacent_colliding += static_cast<std::uint64_t>(
                std::count_if(run.pairs.begin(), run.pairs.end(), [&](const TrianglePair& p) { return shares_vertex(frame, p); }));
            all_candidates += run.stats.counts.candidate_pairs;
        }
    }
    // Fold-overs and piercings between neighbours occur, and are a minority of the pairs
    // that pass the prefilter (most neighbours only touch at what they share).
    std::cout << "colliding pairs sharing a vertex: " << adjacent_colliding << "; candidate pairs: " << all_candidates << "\n";
    EXPECT_GT(adjacent_colliding, 10u);
    EXPECT_LT(adjacent_colliding * 4, all_candidates);
}

TEST(BruteMethod, FlatSheetHasNoSelfPairs) {
    const Frame frame = make_frame({testing::grid_sheet(8, 1.0)});
    const BruteRun run = run_brute(frame, true);
    EXPECT_TRUE(run.pairs.empty());
    EXPECT_GT(run.stats.counts.candidate_pairs, 0u);  // neighbours' boxes touch
}

TEST(BruteMethod, FoldOverAndPiercingNeighboursCollide) {
    const Frame frame = make_frame({folded_mesh()});
    const BruteRun run = run_brute(frame, true);
    EXPECT_EQ(run.pairs, reference_colliding_pairs(frame, true));
    EXPECT_NE(std::find(run.pairs.begin(), run.pairs.end(), TrianglePair{0, 0, 0, 1}), run.pairs.end());
    EXPECT_NE(std::find(run.pairs.begin(), run.pairs.end(), TrianglePair{0, 0, 0, 2}), run.pairs.end());
}

TEST(BruteMethod, KeepsPairsWhoseBoxesOnlyTouch) {
    MeshData below;  // in the plane z = 0
    below.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    below.triangles = {{0, 1, 2}};
    MeshData above;  // one corner on the first triangle, the rest above it: boxes meet at z = 0
    above.vertices = {{1, 1, 0}, {1, 1, 3}, {2, 1, 3}};
    above.triangles = {{0, 1, 2}};
    // Both orders, so each side of every closed comparison is exercised.
    for (const bool below_first : {true, false}) {
        const BruteRun run = run_brute(below_first ? make_frame({below, above}) : make_frame({above, below}), false);
        EXPECT_EQ(run.pairs, (std::vector<TrianglePair>{{0, 0, 1, 0}}));
        EXPECT_EQ(run.stats.counts.candidate_pairs, 1u);
    }
}

TEST(BruteMethod, CountsAreConsistent) {
    const Frame frame = testing::all_frames(testing::random_scene(7))[0];
    const BruteRun run = run_brute(frame, true);
    std::uint64_t expected_box_tests = 0;
    for (std::size_t a = 0; a < frame.objects.size(); ++a) {
        const std::uint64_t n = frame.objects[a].triangle_count();
        expected_box_tests += n * (n - 1) / 2;
        for (std::size_t b = a + 1; b < frame.objects.size(); ++b) expected_box_tests += n * frame.objects[b].triangle_count();
    }
    EXPECT_EQ(run.stats.counts.box_tests, expected_box_tests);
    EXPECT_EQ(run.stats.counts.exact_tests, run.stats.counts.candidate_pairs);
    EXPECT_EQ(run.stats.counts.colliding_pairs, run.pairs.size());
    // Both stages ran (box tests and exact tests above), so both were timed: a stage whose
    // stopwatch is never read stays 0.
    ASSERT_GT(run.stats.counts.exact_tests, 0u);
    EXPECT_GT(run.stats.ms.cull, 0.0);
    EXPECT_GT(run.stats.ms.narrow, 0.0);
}

TEST(BruteMethod, CountsExactFallbacks) {
    // Coplanar overlapping triangles in a tilted plane: the float filter cannot decide the
    // zero orientations. With small integer coordinates every product is exact, so the cheap
    // exact stage decides them (counted as shortcuts); with decimal coordinates that round,
    // the expansions must run (counted as fallbacks).
    MeshData a;  // in the plane z = x + y
    a.vertices = {{0, 0, 0}, {3, 0, 3}, {0, 3, 3}};
    a.triangles = {{0, 1, 2}};
    MeshData b;  // the same plane, overlapping a
    b.vertices = {{1, 1, 2}, {3, 3, 6}, {-1, 2, 1}};
    b.triangles = {{0, 1, 2}};
    const BruteRun run = run_brute(make_frame({a, b}), false);
    EXPECT_EQ(run.pairs.size(), 1u);
    EXPECT_GT(run.stats.counts.exact_shortcuts, 0u);
    EXPECT_EQ(run.stats.counts.exact_fallbacks, 0u);

    MeshData c;  // nearly in that plane: z = x + y rounded, products that round
    c.vertices = {{0.1, 0.7, 0.1 + 0.7}, {2.3, 0.3, 2.3 + 0.3}, {0.3, 1.9, 0.3 + 1.9}};
    c.triangles = {{0, 1, 2}};
    const BruteRun near = run_brute(make_frame({a, c}), false);
    EXPECT_GT(near.stats.counts.exact_fallbacks, 0u);
}

TEST(BruteMethod, TestsOnlyTheGivenObjectPairs) {
    const Frame frame = make_frame({testing::grid_sheet(2, 1.0), testing::grid_sheet(2, 1.0), testing::grid_sheet(2, 1.0)});
    const BruteRun run = run_brute(frame, false, {{0, 2}});
    ASSERT_FALSE(run.pairs.empty());
    for (const TrianglePair& pair : run.pairs) {
        EXPECT_EQ(pair.obj_a, 0u);
        EXPECT_EQ(pair.obj_b, 2u);
    }
}

TEST(BruteMethod, IgnoresSelfPairsWhenSelfCollisionIsOff) {
    const Frame frame = make_frame({folded_mesh()});
    ASSERT_FALSE(reference_colliding_pairs(frame, true).empty());
    const BruteRun run = run_brute(frame, false, {{0, 0}});
    EXPECT_TRUE(run.pairs.empty());
    EXPECT_EQ(run.stats.counts.box_tests, 0u);
}

}  // namespace
}  // namespace collidescope
