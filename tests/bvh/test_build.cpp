// Both builders against the validator on ordinary and degenerate meshes, their determinism
// across thread counts, and the validator's own ability to fail.

#include "bvh/bvh_helpers.hpp"

#include "support/scene_builders.hpp"

#include "bvh/bvh.hpp"
#include "bvh/validate_tree.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

namespace collidescope::bvh {
namespace {

using testing::grid_soup;

struct NamedMesh {
    std::string name;
    MeshData mesh;
};

std::vector<NamedMesh> meshes_to_build() {
    std::mt19937_64 rng(0xb1d);
    std::vector<NamedMesh> meshes;
    meshes.push_back({"grid", testing::grid_sheet(40, 10.0)});
    meshes.push_back({"crumpled", testing::crumpled_sheet(rng, 30, 1.0, true)});
    meshes.push_back({"soup", grid_soup(rng, 20000, 50)});
    meshes.push_back({"tiny soup", grid_soup(rng, 5, 2)});
    MeshData one;
    one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.triangles = {{0, 1, 2}};
    meshes.push_back({"one triangle", one});
    MeshData same;  // every triangle identical: all centroids coincide
    same.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    same.triangles.assign(1000, TriIndices{0, 1, 2});
    meshes.push_back({"coincident", same});
    MeshData points;  // degenerate: points on a line, exponentially spaced (unbalanced SAH)
    for (std::uint32_t i = 0; i < 3000; ++i) {
        points.vertices.push_back({std::ldexp(1.0, static_cast<int>(i % 900) - 450), 0, 0});
        points.triangles.push_back({i, i, i});
    }
    meshes.push_back({"points", points});
    return meshes;
}

TEST(BvhBuild, BothBuildersPassTheValidator) {
    for (const Builder builder : {Builder::Sah, Builder::Lbvh}) {
        for (const std::uint32_t leaf : {1u, 4u, 7u}) {
            for (const NamedMesh& named : meshes_to_build()) {
                SCOPED_TRACE(named.name + (builder == Builder::Sah ? " sah" : " lbvh") + " leaf " + std::to_string(leaf));
                BuildConfig config;
                config.builder = builder;
                config.max_leaf_size = leaf;
                config.parallel_grain = 256;  // exercise the parallel paths on small meshes
                config.refit_grain = 64;
                Tree tree;
                const BuildStats stats = build_tree(named.mesh.triangles, named.mesh.vertices, config, tree);
                EXPECT_EQ(validate(tree, named.mesh.triangles, named.mesh.vertices, {leaf, true}),
                          std::vector<std::string>{});
                EXPECT_EQ(stats.nodes, tree.nodes.size());
                EXPECT_GE(stats.depth, 1u);
                EXPECT_LE(stats.depth, 200u);
                EXPECT_NEAR(tree.built_cost, sah_cost(tree), 1e-9 * tree.built_cost);
            }
        }
    }
}

TEST(BvhBuild, EmptyMeshGivesEmptyTree) {
    Tree tree;
    const BuildStats stats = build_tree({}, {}, BuildConfig{}, tree);
    EXPECT_TRUE(tree.empty());
    EXPECT_EQ(stats.nodes, 0u);
    EXPECT_TRUE(validate(tree, {}, {}).empty());
}

TEST(BvhBuild, SameTreeForEveryThreadCount) {
    std::mt19937_64 rng(77);
    const MeshData mesh = grid_soup(rng, 30000, 80);
    for (const Builder builder : {Builder::Sah, Builder::Lbvh}) {
        BuildConfig config;
        config.builder = builder;
        config.parallel_grain = 512;
        std::vector<Tree> trees;
        for (const int threads : {1, 2, 4}) {
            const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
            Tree tree;
            build_tree(mesh.triangles, mesh.vertices, config, tree);
            trees.push_back(std::move(tree));
        }
        for (std::size_t k = 1; k < trees.size(); ++k) {
            ASSERT_EQ(trees[k].nodes.size(), trees[0].nodes.size());
            EXPECT_EQ(trees[k].triangle_ids, trees[0].triangle_ids);
            for (std::size_t i = 0; i < trees[0].nodes.size(); ++i) {
                ASSERT_EQ(trees[k].nodes[i].box, trees[0].nodes[i].box) << "node " << i;
                ASSERT_EQ(trees[k].nodes[i].index, trees[0].nodes[i].index) << "node " << i;
                ASSERT_EQ(trees[k].nodes[i].count, trees[0].nodes[i].count) << "node " << i;
            }
        }
    }
}

TEST(BvhBuild, SahTreeIsCheaperThanLbvhOnASoup) {
    std::mt19937_64 rng(5);
    const MeshData mesh = grid_soup(rng, 20000, 100);
    Tree sah;
    Tree lbvh;
    BuildConfig config;
    config.builder = Builder::Sah;
    const double sah_cost_value = build_tree(mesh.triangles, mesh.vertices, config, sah).sah_cost;
    config.builder = Builder::Lbvh;
    const double lbvh_cost_value = build_tree(mesh.triangles, mesh.vertices, config, lbvh).sah_cost;
    EXPECT_LT(sah_cost_value, lbvh_cost_value);
}

// The validator must be able to fail: each corruption is reported.
TEST(BvhValidator, ReportsCorruptions) {
    const MeshData mesh = testing::grid_sheet(8, 8.0);
    Tree good;
    build_tree(mesh.triangles, mesh.vertices, BuildConfig{}, good);
    ASSERT_TRUE(validate(good, mesh.triangles, mesh.vertices).empty());
    const auto broken = [&](auto&& corrupt) {
        Tree tree = good;
        corrupt(tree);
        return !validate(tree, mesh.triangles, mesh.vertices).empty();
    };
    EXPECT_TRUE(broken([](Tree& t) { t.nodes[0].box.hi[0] -= 0.5; }));                  // child sticks out
    EXPECT_TRUE(broken([](Tree& t) { t.nodes.back().box.lo[2] += 1e-9; }));              // leaf not containing
    EXPECT_TRUE(broken([](Tree& t) { t.triangle_ids[3] = t.triangle_ids[4]; }));         // a triangle twice
    EXPECT_TRUE(broken([](Tree& t) { std::swap(t.leaf_triangles[0], t.leaf_triangles[5]); }));  // stale copy
    EXPECT_TRUE(broken([](Tree& t) { t.nodes[0].index = 1; }));                           // bad child index
    EXPECT_TRUE(broken([](Tree& t) { t.nodes.pop_back(); }));                             // counts
    EXPECT_TRUE(broken([](Tree& t) { t.refit_plan.top.push_back(0); }));                  // plan overlap
    EXPECT_TRUE(broken([](Tree& t) { t.refit_plan.leaf_ends[0] ^= 1; }));                 // leaf end moved
    EXPECT_TRUE(broken([](Tree& t) { std::swap(t.refit_plan.leaves[0], t.refit_plan.leaves[1]); }));  // leaf order
    EXPECT_TRUE(broken([](Tree& t) { t.refit_plan.inner.pop_back(); }));                  // inner node missing
    EXPECT_TRUE(broken([](Tree& t) { t.refit_plan.subtrees[0].slot_end -= 1; }));         // slots short
    EXPECT_TRUE(broken([](Tree& t) { t.nodes[1].box.lo[0] -= 1; t.nodes[0].box.lo[0] -= 1; }));  // not tight
    // Moving a vertex without a refit: the leaf no longer contains its triangle.
    std::vector<Vec3> moved = mesh.vertices;
    moved[10].z() += 0.25;
    EXPECT_FALSE(validate(good, mesh.triangles, moved, {4, false}).empty());
}

}  // namespace
}  // namespace collidescope::bvh
