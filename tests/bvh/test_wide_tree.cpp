// The wide layout (bvh/wide_tree.hpp) and its traversal (traverse_wide.cpp): rounding that
// brackets every double, wide boxes that contain the binary ones, candidates equal to the
// binary traversal's and to the all-pairs box filter; and TreeBuilder's kept working memory
// giving the trees of fresh builds.

#include "bvh/bvh_helpers.hpp"
#include "support/scene_builders.hpp"
#include "support/sweep_size.hpp"

#include "bvh/bvh.hpp"
#include "bvh/traverse.hpp"
#include "bvh/wide_tree.hpp"
#include "geometry/float32.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <limits>
#include <random>

namespace collidescope::bvh {
namespace {

constexpr float k_inf = std::numeric_limits<float>::infinity();

// A float widened out of line, so that the comparisons see the float a rounding returned: inline,
// GCC 12's SLP pass may drop a double -> float -> double round trip (docs/how-to/toolchain.md).
[[gnu::noinline]] double widened(float f) { return f; }

TEST(WideTree, RoundingBracketsEveryDouble) {
    const std::uint64_t seed = 41;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> values{0.0, -0.0, 1e-300, -1e-300, 1e-45, 1.4e-45, -1e-39, 1e38, -1e38, 1e300, -1e300,
                               3.4028234663852886e38, -3.4028234663852886e38, 3.5e38, 0.1, -0.1, 1.0, 1.0 / 3};
    for (int i = 0; i < 200000; ++i) values.push_back(unit(rng) * std::pow(10.0, static_cast<int>(unit(rng) * 45)));
    for (int i = 0; i < 100000; ++i) {  // floats and their double neighbours: the rounding edges
        const double f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
        if (!std::isfinite(f)) continue;
        values.insert(values.end(), {f, std::nextafter(f, 1e300), std::nextafter(f, -1e300)});
    }
    for (const double v : values) {
        const double down = widened(round_down(v)), up = widened(round_up(v));
        ASSERT_LE(down, v) << std::hexfloat << v;
        ASSERT_GE(up, v) << std::hexfloat << v;
        // Tight: a few float steps, not a loose box.
        if (std::fabs(v) > 1e-30 && std::fabs(v) < 1e38) {
            ASSERT_LE((up - down) / std::fabs(v), 1e-6) << v;
        }
        // The exact pair: the largest float not above v (the next one is above it), and the
        // smallest not below.
        const float below = float32_below(v), above = float32_above(v);
        ASSERT_LE(widened(below), v) << std::hexfloat << v;
        ASSERT_GT(widened(std::nextafter(below, k_inf)), v) << std::hexfloat << v;
        ASSERT_GE(widened(above), v) << std::hexfloat << v;
        ASSERT_LT(widened(std::nextafter(above, -k_inf)), v) << std::hexfloat << v;
    }
    EXPECT_EQ(round_down(std::numeric_limits<double>::infinity()), k_inf);
    EXPECT_EQ(round_up(-std::numeric_limits<double>::infinity()), -k_inf);
    EXPECT_EQ(round_down(1e300), std::numeric_limits<float>::max());
    EXPECT_EQ(round_up(-1e300), std::numeric_limits<float>::lowest());
    EXPECT_TRUE(std::isnan(round_down(std::nan(""))));
    EXPECT_TRUE(std::isnan(round_up(std::nan(""))));
}

bool float_box_contains(const WideNode& node, int slot, const Aabb& box) {
    for (int k = 0; k < 3; ++k) {
        if (!(node.lo[k][slot] <= box.lo[k] && box.hi[k] <= node.hi[k][slot])) return false;
    }
    return true;
}

// Walks the wide layout: every binary leaf reached exactly once, as a leaf entry naming its
// triangle slots; every slot's float box containing the double boxes of the triangles below it.
void expect_wide_layout_fits(const Tree& tree) {
    ASSERT_TRUE(wide_fitted(tree));
    const WideTree& wide = tree.wide;
    std::map<std::uint32_t, std::uint32_t> binary_leaves;  // first slot -> count
    for (const Node& node : tree.nodes) {
        if (node.is_leaf()) binary_leaves[node.index] = node.count;
    }
    if (tree.nodes[0].is_leaf()) {
        EXPECT_EQ(wide_root(tree), wide_leaf(0, tree.nodes[0].count));
        EXPECT_TRUE(wide.nodes.empty());
        return;
    }
    EXPECT_EQ(wide_root(tree), 0u);
    const auto leaves_below = [&](auto&& self, std::uint32_t entry, std::vector<std::uint32_t>& out) -> void {
        if (is_wide_leaf(entry)) {
            out.push_back(entry);
            return;
        }
        for (const std::uint32_t child : wide.nodes[entry].child) {
            if (child != k_wide_empty) self(self, child, out);
        }
    };
    std::map<std::uint32_t, int> reached;  // first slot -> times a leaf entry names it
    for (std::uint32_t w = 0; w < wide.nodes.size(); ++w) {
        int children = 0;
        for (int s = 0; s < 4; ++s) {
            const std::uint32_t child = wide.nodes[w].child[s];
            if (child == k_wide_empty) {
                EXPECT_EQ(wide.nodes[w].lo[0][s], k_inf);
                continue;
            }
            ++children;
            if (is_wide_leaf(child)) {
                ++reached[wide_leaf_first(child)];
                // The leaf's own float box, kept at its first slot, is the box its slot holds.
                ASSERT_EQ(wide.leaf_box_at.size(), tree.leaf_boxes.size());
                const FloatBox& kept = wide.leaf_box_at[wide_leaf_first(child)];
                for (int k = 0; k < 3; ++k) {
                    EXPECT_EQ(kept.lo[k], wide.nodes[w].lo[k][s]) << "wide " << w << " slot " << s;
                    EXPECT_EQ(kept.hi[k], wide.nodes[w].hi[k][s]) << "wide " << w << " slot " << s;
                }
            }
            std::vector<std::uint32_t> leaves;
            leaves_below(leaves_below, child, leaves);
            for (const std::uint32_t leaf : leaves) {
                const std::uint32_t first = wide_leaf_first(leaf);
                ASSERT_EQ(binary_leaves.count(first), 1u) << "wide " << w << " slot " << s;
                ASSERT_EQ(wide_leaf_count(leaf), binary_leaves[first]);
                for (std::uint32_t t = first; t < first + wide_leaf_count(leaf); ++t) {
                    ASSERT_TRUE(float_box_contains(wide.nodes[w], s, tree.leaf_boxes[t])) << "wide " << w << " slot " << s;
                }
            }
        }
        EXPECT_GE(children, 2) << "wide node " << w;
    }
    EXPECT_EQ(reached.size(), binary_leaves.size());
    for (const auto& [first, times] : reached) EXPECT_EQ(times, 1) << "leaf at slot " << first;
}

std::vector<Vec3> jiggled(std::mt19937_64& rng, std::vector<Vec3> vertices, double step) {
    std::uniform_int_distribution<int> d(-2, 2);
    for (Vec3& v : vertices) v += step * Vec3(d(rng), d(rng), d(rng));
    return vertices;
}

TEST(WideTraverse, CandidatesAreTheBinaryTraversalsAndTheOverlappingBoxes) {
    const std::uint64_t seed = 43;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    int with_candidates = 0;  // frames whose meshes overlap somewhere (most of them)
    for (int round = 0; round < testing::sweep_size(8, 2); ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        MeshData a = round % 2 == 0 ? testing::grid_soup(rng, 700, 8) : testing::crumpled_sheet(rng, 18, 1.0, true);
        MeshData b = testing::translated(round % 4 < 2 ? testing::grid_soup(rng, 500, 8)
                                                       : testing::crumpled_sheet(rng, 14, 1.0, true),
                                         Vec3(1.5, 0.5, 0.25 * round));
        for (const Builder builder : {Builder::Sah, Builder::Lbvh}) {
            BuildConfig config;
            config.builder = builder;
            // 1 to 8 triangles a leaf (past 4: several vector loads); 12: no wide layout.
            config.max_leaf_size = round == 7 ? 12 : 1 + static_cast<std::uint32_t>(round);
            config.refit_grain = round % 2 == 0 ? 32 : 2048;  // many refit subtrees and top nodes, or one
            const bool wide_layout = config.max_leaf_size <= k_wide_max_leaf;
            Tree tree_a;
            Tree tree_b;
            build_tree(a.triangles, a.vertices, config, tree_a);
            build_tree(b.triangles, b.vertices, config, tree_b);
            for (int frame = 0; frame < 4; ++frame) {
                SCOPED_TRACE("frame " + std::to_string(frame));
                // Frame 0: built, never fitted. Frames 1 and 2: moved and refit, which keeps a
                // fitted layout fitted on the way. Frame 3: A built again, which collapses and
                // fits a layout that was in use within the build.
                if (frame > 0) {
                    a.vertices = jiggled(rng, a.vertices, 0.125);
                    b.vertices = jiggled(rng, b.vertices, 0.125);
                    if (frame == 3) {
                        build_tree(a.triangles, a.vertices, config, tree_a);
                    } else {
                        refit(tree_a, a.triangles, a.vertices);
                    }
                    refit(tree_b, b.triangles, b.vertices);
                }
                const std::vector<MeshView> views{{&tree_a, a.triangles, a.vertices}, {&tree_b, b.triangles, b.vertices}};
                std::vector<WorkItem> before_fit;
                add_pair_root(0, 1, views, before_fit);
                ASSERT_EQ(before_fit.size(), 1u);
                EXPECT_EQ(before_fit[0].wide, wide_layout && frame > 0);
                if (wide_layout && frame > 0) {  // fitted by refit and build alone
                    expect_wide_layout_fits(tree_a);
                    expect_wide_layout_fits(tree_b);
                }
                fit_wide(tree_a);
                fit_wide(tree_b);
                if (wide_layout) {
                    expect_wide_layout_fits(tree_a);
                    expect_wide_layout_fits(tree_b);
                }
                std::vector<WorkItem> roots;
                add_pair_root(0, 1, views, roots);
                const std::vector<TrianglePair> expected = testing::box_pairs(a, &b);
                if (!overlaps(tree_a.nodes[0].box, tree_b.nodes[0].box)) {  // no root: nothing to find
                    EXPECT_TRUE(roots.empty());
                    EXPECT_TRUE(expected.empty());
                    continue;
                }
                ASSERT_EQ(roots.size(), 1u);
                EXPECT_EQ(roots[0].wide, wide_layout);
                with_candidates += !expected.empty();
                for (const std::uint32_t items : {1u, 256u}) {
                    std::vector<TrianglePair> wide_candidates;
                    std::vector<TrianglePair> binary_candidates;
                    const TraversalStats stats = traverse(roots, views, {items}, wide_candidates);
                    traverse({{0, 1, 0, 0}}, views, {items}, binary_candidates);
                    std::sort(wide_candidates.begin(), wide_candidates.end());
                    std::sort(binary_candidates.begin(), binary_candidates.end());
                    EXPECT_EQ(wide_candidates, expected);
                    EXPECT_EQ(binary_candidates, expected);
                    EXPECT_EQ(stats.candidate_pairs, wide_candidates.size());
                    EXPECT_GT(stats.nodes_visited, 0u);
                }
            }
        }
    }
    EXPECT_GE(with_candidates, 30);
}

// Wide candidates of two meshes against the all-pairs box filter, both orders.
void expect_wide_candidates(const MeshData& a, const MeshData& b, BuildConfig config) {
    Tree tree_a;
    Tree tree_b;
    build_tree(a.triangles, a.vertices, config, tree_a);
    build_tree(b.triangles, b.vertices, config, tree_b);
    fit_wide(tree_a);
    fit_wide(tree_b);
    expect_wide_layout_fits(tree_a);
    expect_wide_layout_fits(tree_b);
    for (const bool swapped : {false, true}) {
        SCOPED_TRACE(swapped ? "swapped" : "in order");
        const MeshData& x = swapped ? b : a;
        const MeshData& y = swapped ? a : b;
        const Tree& tx = swapped ? tree_b : tree_a;
        const Tree& ty = swapped ? tree_a : tree_b;
        const std::vector<MeshView> views{{&tx, x.triangles, x.vertices}, {&ty, y.triangles, y.vertices}};
        std::vector<WorkItem> roots;
        add_pair_root(0, 1, views, roots);
        ASSERT_EQ(roots.size(), 1u);
        EXPECT_TRUE(roots[0].wide);
        std::vector<TrianglePair> candidates;
        traverse(roots, views, {}, candidates);
        std::sort(candidates.begin(), candidates.end());
        const std::vector<TrianglePair> expected = testing::box_pairs(x, &y);
        EXPECT_FALSE(expected.empty());
        EXPECT_EQ(candidates, expected);
    }
}

TEST(WideTraverse, RootLeavesAndCoordinatesPastFloatRange) {
    const std::uint64_t seed = 45;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    // A tree that is one leaf (a root entry that is a leaf) against a larger one.
    const MeshData sheet = testing::crumpled_sheet(rng, 16, 1.0, true);
    MeshData tiny;
    for (int k = 0; k < 3; ++k) {
        const auto base = static_cast<std::uint32_t>(tiny.vertices.size());
        tiny.vertices.insert(tiny.vertices.end(), {Vec3(2.0 + k, 2, -2), Vec3(3.0 + k, 3, 2), Vec3(2.5 + k, 6, 0)});
        tiny.triangles.push_back({base, base + 1, base + 2});
    }
    {
        SCOPED_TRACE("a root leaf");
        expect_wide_candidates(tiny, sheet, BuildConfig{});
    }
    // Coordinates past float range on every axis: boxes round to infinities and overlap
    // every float box, the unused slots' empty boxes included (those must not be followed).
    const auto huge = [](MeshData mesh) {
        for (Vec3& v : mesh.vertices) v = (v - Vec3(4, 4, 4)) * 1e39;
        return mesh;
    };
    {
        SCOPED_TRACE("past float range");
        expect_wide_candidates(huge(testing::grid_soup(rng, 300, 8)), huge(testing::grid_soup(rng, 250, 8)),
                               BuildConfig{});
    }
}

TEST(WideTraverse, BoxesApartGiveNoRootAndMarksKeepTheBinaryPath) {
    const MeshData a = testing::grid_sheet(10, 1.0);
    const MeshData b = testing::translated(testing::grid_sheet(10, 1.0), Vec3(5, 0, 0));
    Tree tree_a;
    Tree tree_b;
    build_tree(a.triangles, a.vertices, BuildConfig{}, tree_a);
    build_tree(b.triangles, b.vertices, BuildConfig{}, tree_b);
    fit_wide(tree_a);
    fit_wide(tree_b);
    std::vector<MeshView> views{{&tree_a, a.triangles, a.vertices}, {&tree_b, b.triangles, b.vertices}};
    std::vector<WorkItem> roots;
    add_pair_root(0, 1, views, roots);
    EXPECT_TRUE(roots.empty());
    const std::vector<std::uint8_t> alive(a.triangles.size(), 1);
    views[0].alive_triangles = alive;
    add_pair_root(0, 1, views, roots);
    ASSERT_EQ(roots.size(), 1u);
    EXPECT_FALSE(roots[0].wide);
}

void expect_same_tree(const Tree& got, const Tree& want) {
    ASSERT_EQ(got.nodes.size(), want.nodes.size());
    for (std::size_t i = 0; i < want.nodes.size(); ++i) {
        ASSERT_EQ(got.nodes[i].box, want.nodes[i].box) << "node " << i;
        ASSERT_EQ(got.nodes[i].index, want.nodes[i].index) << "node " << i;
        ASSERT_EQ(got.nodes[i].count, want.nodes[i].count) << "node " << i;
    }
    EXPECT_EQ(got.triangle_ids, want.triangle_ids);
    EXPECT_EQ(got.leaf_triangles, want.leaf_triangles);
    EXPECT_EQ(got.leaf_boxes, want.leaf_boxes);
    EXPECT_EQ(got.refit_plan.leaves, want.refit_plan.leaves);
    EXPECT_EQ(got.refit_plan.inner, want.refit_plan.inner);
    EXPECT_EQ(got.refit_plan.top, want.refit_plan.top);
    EXPECT_EQ(got.refit_plan.leaf_ends, want.refit_plan.leaf_ends);
    EXPECT_EQ(got.patches.loop_vertices, want.patches.loop_vertices);
    EXPECT_EQ(got.patches.loop_size, want.patches.loop_size);
    EXPECT_EQ(got.patches.sides, want.patches.sides);
    EXPECT_EQ(got.built_cost, want.built_cost);
}

TEST(TreeBuilder, RebuildsWithKeptWorkingMemoryGiveTheTreesOfFreshBuilds) {
    const std::uint64_t seed = 44;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    TreeBuilder builder;
    Tree reused;  // rebuilt again and again: larger, smaller, other builder, patches on and off
    for (int round = 0; round < 8; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const MeshData mesh = round % 2 == 0 ? testing::crumpled_sheet(rng, 10 + 7 * (round % 3), 1.0, true)
                                             : testing::grid_soup(rng, 300 + 400 * (round % 3), 8);
        BuildConfig config;
        config.builder = round % 3 == 0 ? Builder::Sah : Builder::Lbvh;
        config.surface_patches = round % 2 == 0;
        config.refit_grain = 64;
        Tree fresh;
        build_tree(mesh.triangles, mesh.vertices, config, fresh);
        const std::uint64_t builds = reused.builds;
        builder.build(mesh.triangles, mesh.vertices, config, reused);
        EXPECT_EQ(reused.builds, builds + 1);
        expect_same_tree(reused, fresh);
    }
}

}  // namespace
}  // namespace collidescope::bvh
