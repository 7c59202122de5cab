// Refit against fresh builds and the validator, the quality measure, and the traversal's
// candidates against the obvious all-pairs box filter.

#include "bvh/bvh_helpers.hpp"
#include "support/scene_builders.hpp"

#include "bvh/bvh.hpp"
#include "bvh/traverse.hpp"
#include "bvh/validate_tree.hpp"
#include "collidescope/geometry.hpp"
#include "geometry/adjacent_filter.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <random>

namespace collidescope::bvh {
namespace {

// Every vertex moved by a random multiple of `step` per axis (up to `range` steps).
std::vector<Vec3> jiggle(std::mt19937_64& rng, std::vector<Vec3> vertices, double step, int range) {
    std::uniform_int_distribution<int> d(-range, range);
    for (Vec3& v : vertices) v += step * Vec3(d(rng), d(rng), d(rng));
    return vertices;
}

TEST(BvhRefit, FitsMovedVerticesExactly) {
    std::mt19937_64 rng(3);
    const MeshData mesh = testing::crumpled_sheet(rng, 40, 1.0, true);
    for (const Builder builder : {Builder::Sah, Builder::Lbvh}) {
        BuildConfig config;
        config.builder = builder;
        config.refit_grain = 32;
        Tree tree;
        build_tree(mesh.triangles, mesh.vertices, config, tree);
        std::vector<Vec3> vertices = mesh.vertices;
        for (int frame = 0; frame < 5; ++frame) {
            vertices = jiggle(rng, vertices, 0.125, 2);
            const RefitStats stats = refit(tree, mesh.triangles, vertices);
            EXPECT_EQ(validate(tree, mesh.triangles, vertices), std::vector<std::string>{}) << "frame " << frame;
            EXPECT_EQ(stats.nodes, tree.nodes.size());
            EXPECT_NEAR(stats.sah_cost, sah_cost(tree), 1e-9 * stats.sah_cost);
        }
    }
}

TEST(BvhRefit, QualityIsOneUnmovedAndGrowsWhenTrianglesScatter) {
    std::mt19937_64 rng(4);
    const MeshData mesh = testing::grid_sheet(40, 10.0);
    Tree tree;
    build_tree(mesh.triangles, mesh.vertices, BuildConfig{}, tree);
    EXPECT_DOUBLE_EQ(refit(tree, mesh.triangles, mesh.vertices).quality, 1.0);
    // A uniform scale keeps the structure's quality (the cost is relative to the root).
    std::vector<Vec3> scaled = mesh.vertices;
    for (Vec3& v : scaled) v *= 4.0;
    EXPECT_NEAR(refit(tree, mesh.triangles, scaled).quality, 1.0, 1e-12);
    // Scattering the vertices (an explosion) stretches the boxes: the quality degrades.
    const double scattered = refit(tree, mesh.triangles, jiggle(rng, mesh.vertices, 1.0, 10)).quality;
    EXPECT_GT(scattered, 2.0);
}

TEST(BvhRefit, SameBoxesForEveryThreadCount) {
    std::mt19937_64 rng(8);
    const MeshData mesh = testing::grid_soup(rng, 20000, 60);
    const std::vector<Vec3> moved = jiggle(rng, mesh.vertices, 0.5, 3);
    std::vector<LargeVector<Node>> results;
    for (const int threads : {1, 2, 4}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        BuildConfig config;
        config.refit_grain = 128;
        Tree tree;
        build_tree(mesh.triangles, mesh.vertices, config, tree);
        refit(tree, mesh.triangles, moved);
        results.push_back(tree.nodes);
    }
    for (std::size_t k = 1; k < results.size(); ++k) {
        ASSERT_EQ(results[k].size(), results[0].size());
        for (std::size_t i = 0; i < results[0].size(); ++i) ASSERT_EQ(results[k][i].box, results[0][i].box);
    }
}

// The swept refit against the obvious way: each node's box the union of its boxes refit to
// either end, each leaf box the union of the triangle's boxes at both ends.
TEST(BvhRefit, SweptBoxesAreTheUnionOfBothEndsBoxes) {
    std::mt19937_64 rng(9);
    const MeshData mesh = testing::crumpled_sheet(rng, 30, 1.0, true);
    const std::vector<Vec3> from = jiggle(rng, mesh.vertices, 0.125, 2), to = jiggle(rng, mesh.vertices, 0.125, 4);
    BuildConfig config;
    config.refit_grain = 32;
    Tree swept, at_from, at_to;
    for (Tree* tree : {&swept, &at_from, &at_to}) build_tree(mesh.triangles, mesh.vertices, config, *tree);
    refit_swept(swept, mesh.triangles, from, to);
    refit(at_from, mesh.triangles, from);
    refit(at_to, mesh.triangles, to);
    for (std::size_t i = 0; i < swept.nodes.size(); ++i) {
        Aabb both = at_from.nodes[i].box;
        both.grow(at_to.nodes[i].box);
        ASSERT_EQ(swept.nodes[i].box, both) << "node " << i;
    }
    for (std::size_t k = 0; k < swept.leaf_boxes.size(); ++k) {
        Aabb both = at_from.leaf_boxes[k];
        both.grow(at_to.leaf_boxes[k]);
        ASSERT_EQ(swept.leaf_boxes[k], both) << "slot " << k;
    }
}

// The build over swept boxes against the obvious way: a valid tree (structure, coverage,
// every box holding its triangles at both ends, checked by the validator on each end, and
// exactly the union of their boxes at both ends, by hand), the same boxes a swept refit of it
// gives, and a quality reference of 1 for that refit; for both builders, a tree with patches,
// a root that is a leaf, and a wide layout in use (left stale for fit_wide).
TEST(BvhBuild, SweptBuildFitsEachBoxToBothEnds) {
    for (const std::uint64_t seed : {10u, 11u, 12u, 13u, 14u}) {
        std::mt19937_64 rng(seed);
        SCOPED_TRACE("seed " + std::to_string(seed));
        const MeshData mesh = seed == 10   ? testing::crumpled_sheet(rng, 30, 1.0, true)
                              : seed == 13 ? testing::grid_soup(rng, 3, 2)  // one leaf
                                           : testing::grid_soup(rng, 5000, 20);
        const std::vector<Vec3> from = jiggle(rng, mesh.vertices, 0.25, 2), to = jiggle(rng, mesh.vertices, 0.25, 4);
        BuildConfig config;
        config.refit_grain = 32;
        config.builder = seed == 11 ? Builder::Sah : Builder::Lbvh;
        config.surface_patches = seed == 10;
        Tree tree;
        TreeBuilder builder;
        if (seed == 14) {  // a layout in use before the build
            build_swept_tree(mesh.triangles, to, from, config, tree);
            fit_wide(tree);
            ASSERT_TRUE(wide_fitted(tree));
        }
        const BuildStats built = seed == 12 ? builder.build_swept(mesh.triangles, from, to, config, tree)
                                            : build_swept_tree(mesh.triangles, from, to, config, tree);
        EXPECT_FALSE(wide_fitted(tree));
        EXPECT_EQ(tree.patches.empty(), seed != 10);
        EXPECT_EQ(tree.nodes.size() == 1, seed == 13);
        ValidateOptions loose;
        loose.tight = false;  // each box also holds the other end
        EXPECT_EQ(validate(tree, mesh.triangles, from, loose), std::vector<std::string>{});
        EXPECT_EQ(validate(tree, mesh.triangles, to, loose), std::vector<std::string>{});
        for (std::size_t k = 0; k < tree.leaf_boxes.size(); ++k) {
            Aabb both = triangle_box(tree.leaf_triangles[k], from);
            both.grow(triangle_box(tree.leaf_triangles[k], to));
            ASSERT_EQ(tree.leaf_boxes[k], both) << "slot " << k;
            ASSERT_EQ(tree.leaf_triangles[k], mesh.triangles[tree.triangle_ids[k]]) << "slot " << k;
        }
        const LargeVector<Node> nodes = tree.nodes;
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            Aabb expected;
            if (nodes[i].is_leaf()) {
                for (std::uint32_t k = 0; k < nodes[i].count; ++k) expected.grow(tree.leaf_boxes[nodes[i].index + k]);
            } else {
                expected = nodes[i + 1].box;
                expected.grow(nodes[nodes[i].index].box);
            }
            ASSERT_EQ(nodes[i].box, expected) << "node " << i;
        }
        EXPECT_DOUBLE_EQ(built.sah_cost, sah_cost(tree));
        const RefitStats refit_again = refit_swept(tree, mesh.triangles, from, to);
        for (std::size_t i = 0; i < nodes.size(); ++i) ASSERT_EQ(tree.nodes[i].box, nodes[i].box) << "node " << i;
        EXPECT_DOUBLE_EQ(refit_again.quality, 1.0);
        if (seed == 14) {
            fit_wide(tree);
            EXPECT_TRUE(wide_fitted(tree));
        }
    }
}

TEST(BvhTraverse, CandidatesAreExactlyTheOverlappingTriangleBoxes) {
    std::mt19937_64 rng(21);
    for (int round = 0; round < 6; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const MeshData a = round % 2 == 0 ? testing::grid_soup(rng, 600, 8) : testing::crumpled_sheet(rng, 16, 1.0, true);
        const MeshData b = testing::translated(testing::grid_soup(rng, 500, 8), Vec3(2, 1, 0));
        for (const Builder builder : {Builder::Sah, Builder::Lbvh}) {
            BuildConfig config;
            config.builder = builder;
            config.max_leaf_size = 1 + static_cast<std::uint32_t>(round);
            Tree tree_a;
            Tree tree_b;
            build_tree(a.triangles, a.vertices, config, tree_a);
            build_tree(b.triangles, b.vertices, config, tree_b);
            const std::vector<MeshView> views{{&tree_a, a.triangles, a.vertices}, {&tree_b, b.triangles, b.vertices}};
            for (const std::uint32_t items : {1u, 256u}) {
                std::vector<TrianglePair> pair_candidates;
                std::vector<TrianglePair> self_candidates;
                const TraversalStats pair_stats = traverse({{0, 1, 0, 0}}, views, {items}, pair_candidates);
                const TraversalStats self_stats = traverse({{0, 0, 0, 0}}, views, {items}, self_candidates);
                std::sort(pair_candidates.begin(), pair_candidates.end());
                std::sort(self_candidates.begin(), self_candidates.end());
                EXPECT_EQ(pair_candidates, testing::box_pairs(a, &b));
                // Within one object, the pairs adjacent_apart proves apart are not candidates
                // (the slow way: every box pair through it, each one it drops checked against
                // the exact self rule).
                std::vector<TrianglePair> self_expected;
                std::uint64_t apart = 0;
                for (const TrianglePair& pair : testing::box_pairs(a, nullptr)) {
                    const TriIndices& ta = a.triangles[pair.tri_a];
                    const TriIndices& tb = a.triangles[pair.tri_b];
                    if (!filter::adjacent_apart(ta, tb, a.vertices.data())) {
                        self_expected.push_back(pair);
                        continue;
                    }
                    ++apart;
                    const auto corners = [&](const TriIndices& t) {
                        return std::array<Vec3, 3>{a.vertices[t[0]], a.vertices[t[1]], a.vertices[t[2]]};
                    };
                    EXPECT_FALSE(self_triangles_collide(ta, corners(ta), tb, corners(tb)));
                }
                EXPECT_EQ(self_candidates, self_expected);
                EXPECT_EQ(self_stats.adjacent_apart, apart);
                EXPECT_EQ(pair_stats.adjacent_apart, 0u);
                if (round % 2 == 1) {
                    EXPECT_GT(apart, 0u);  // the crumpled sheet has neighbours
                }
                EXPECT_EQ(pair_stats.candidate_pairs, pair_candidates.size());
                EXPECT_EQ(self_stats.candidate_pairs, self_candidates.size());
                EXPECT_GT(pair_stats.nodes_visited, 0u);
            }
        }
    }
}

TEST(BvhTraverse, PrunesSeparatedParts) {
    // Two 30x30 sheets crossing along one strip: a small share of the pairs is near.
    const MeshData a = testing::grid_sheet(30, 30.0);
    MeshData b = testing::grid_sheet(30, 30.0);
    for (Vec3& v : b.vertices) v = Vec3(v.x() + 29.0, v.y(), v.y() - 15.0);  // tilted, overlapping x in [29, 30]
    Tree tree_a;
    Tree tree_b;
    build_tree(a.triangles, a.vertices, BuildConfig{}, tree_a);
    build_tree(b.triangles, b.vertices, BuildConfig{}, tree_b);
    const std::vector<MeshView> views{{&tree_a, a.triangles, a.vertices}, {&tree_b, b.triangles, b.vertices}};
    std::vector<TrianglePair> candidates;
    const TraversalStats stats = traverse({{0, 1, 0, 0}}, views, {}, candidates);
    std::sort(candidates.begin(), candidates.end());
    EXPECT_EQ(candidates, testing::box_pairs(a, &b));
    EXPECT_FALSE(candidates.empty());
    EXPECT_LT(stats.box_tests * 100, std::uint64_t{a.triangles.size()} * b.triangles.size());
}

TEST(BvhTraverse, CountsDoNotDependOnThreads) {
    std::mt19937_64 rng(22);
    const MeshData a = testing::crumpled_sheet(rng, 40, 1.0, true);
    Tree tree;
    build_tree(a.triangles, a.vertices, BuildConfig{}, tree);
    const std::vector<MeshView> views{{&tree, a.triangles, a.vertices}};
    std::vector<TraversalStats> stats;
    for (const int threads : {1, 2, 4}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        std::vector<TrianglePair> candidates;
        stats.push_back(traverse({{0, 0, 0, 0}}, views, {}, candidates));
    }
    for (const TraversalStats& s : stats) {
        EXPECT_EQ(s.nodes_visited, stats[0].nodes_visited);
        EXPECT_EQ(s.box_tests, stats[0].box_tests);
        EXPECT_EQ(s.candidate_pairs, stats[0].candidate_pairs);
    }
}

}  // namespace
}  // namespace collidescope::bvh
