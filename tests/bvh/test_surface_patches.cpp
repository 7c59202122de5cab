// Surface patches (bvh/surface_patches.hpp): each node's boundary loop against a slow
// reference (edges counted with their orientation in a map), the refit's sides against
// orient2d, and soundness node by node: wherever a node is proven embedded, no pair of its
// triangles collides under the self rule (all pairs tested), on flat, waved, crumpled,
// folded, slit and ramp-shaped sheets.

#include "bvh/surface_patches.hpp"

#include "support/scene_builders.hpp"

#include "collidescope/geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace collidescope::bvh {
namespace {

Tree patched_tree(const MeshData& mesh, Builder builder = Builder::Lbvh) {
    BuildConfig config;
    config.builder = builder;
    config.surface_patches = true;
    config.parallel_grain = 64;
    config.refit_grain = 16;
    Tree tree;
    build_tree(mesh.triangles, mesh.vertices, config, tree);
    return tree;
}

/// The triangles below `node` (leaf order).
std::vector<TriIndices> triangles_below(const Tree& tree, std::uint32_t node) {
    std::vector<TriIndices> out;
    std::vector<std::uint32_t> stack{node};
    while (!stack.empty()) {
        const Node& n = tree.nodes[stack.back()];
        const std::uint32_t at = stack.back();
        stack.pop_back();
        if (n.is_leaf()) {
            for (std::uint32_t k = 0; k < n.count; ++k) out.push_back(tree.leaf_triangles[n.index + k]);
        } else {
            stack.push_back(at + 1);
            stack.push_back(n.index);
        }
    }
    return out;
}

/// The boundary chain of `triangles` the slow way: directed edge (u, v) -> net count.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> boundary_reference(const std::vector<TriIndices>& triangles) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;
    for (const TriIndices& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = t[k], v = t[(k + 1) % 3];
            if (u < v) ++net[{u, v}];
            else --net[{v, u}];
        }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& [edge, count] : net) {
        if (count == 1) directed[edge] = 1;
        if (count == -1) directed[{edge.second, edge.first}] = 1;
        if (count > 1 || count < -1) directed[edge] = count;  // not a loop
    }
    return directed;
}

/// Checks every node's loop against the reference: a loop's edges are exactly the node's
/// boundary edges, each once, in order.
void expect_loops_match(const Tree& tree, std::uint32_t* with_loop = nullptr) {
    for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
        const std::uint32_t size = tree.patches.loop_size[i];
        const std::vector<TriIndices> below = triangles_below(tree, i);
        ASSERT_EQ(tree.patches.triangles[i], below.size());
        if (size == 0) continue;
        if (with_loop) ++*with_loop;
        const auto reference = boundary_reference(below);
        ASSERT_EQ(reference.size(), size) << "node " << i;
        const std::uint32_t* loop = tree.patches.loop_vertices.data() + tree.patches.loop_begin[i];
        for (std::uint32_t k = 0; k < size; ++k) {
            const auto it = reference.find({loop[k], loop[(k + 1) % size]});
            ASSERT_NE(it, reference.end()) << "node " << i << " corner " << k;
            EXPECT_EQ(it->second, 1);
        }
    }
}

/// Wherever a node is proven embedded, none of its triangle pairs collides (all pairs).
/// Returns how many nodes were proven embedded.
std::uint32_t expect_embedded_sound(const Tree& tree, const MeshData& mesh) {
    std::uint32_t embedded = 0;
    for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
        if (!patch_is_embedded(tree, i, mesh.vertices)) continue;
        ++embedded;
        const std::vector<TriIndices> below = triangles_below(tree, i);
        for (std::size_t a = 0; a < below.size(); ++a)
            for (std::size_t b = a + 1; b < below.size(); ++b) {
                const auto corners = [&](const TriIndices& t) {
                    return std::array<Vec3, 3>{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
                };
                if (self_triangles_collide(below[a], corners(below[a]), below[b], corners(below[b]))) {
                    ADD_FAILURE() << "node " << i << " proven embedded, yet two of its triangles collide";
                    return embedded;
                }
            }
    }
    return embedded;
}

TEST(SurfacePatches, FlatSheetIsOneLoopAroundItsOutlineAndEmbedded) {
    const MeshData sheet = testing::grid_sheet(8, 8.0);
    const Tree tree = patched_tree(sheet);
    EXPECT_EQ(tree.patches.loop_size[0], 32u);  // the outline, 4 x 8 edges
    const std::uint8_t sides = tree.patches.sides[0];
    EXPECT_NE(sides & 0x30, 0);                 // one orientation along z ...
    EXPECT_EQ(sides & 0x0f, 0);                 // ... none along x or y: the sheet is edge-on
    EXPECT_TRUE(patch_is_embedded(tree, 0, sheet.vertices));
    expect_loops_match(tree);
}

TEST(SurfacePatches, SurfaceLikeTellsSheetsFromSoups) {
    EXPECT_TRUE(surface_like(testing::grid_sheet(6, 1.0).triangles));
    EXPECT_TRUE(surface_like(testing::helix_ramp(1.5, [](double) { return 0.0; }).triangles));
    std::mt19937_64 rng(3);
    EXPECT_FALSE(surface_like(testing::grid_soup(rng, 200, 4).triangles));  // no vertex shared
    EXPECT_TRUE(surface_like(std::vector<TriIndices>{}));                  // nothing to lose
}

TEST(SurfacePatches, SidesAreTheCertifiedOrientationsOfEveryTriangleBelow) {
    std::mt19937_64 rng(5);
    const MeshData mesh = testing::crumpled_sheet(rng, 12, 0.3, true);
    const Tree tree = patched_tree(mesh);
    for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
        std::uint8_t expected = 0x3f;
        for (const TriIndices& t : triangles_below(tree, i)) {
            std::uint8_t bits = 0;
            for (int k = 0; k < 3; ++k) {
                const int s = orient2d(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], k);
                bits |= static_cast<std::uint8_t>((s > 0 ? 1u : 0u) << (2 * k));
                bits |= static_cast<std::uint8_t>((s < 0 ? 2u : 0u) << (2 * k));
            }
            expected &= bits;
        }
        // Certified bits are exact signs; the filter may only leave a bit unset.
        EXPECT_EQ(tree.patches.sides[i] & ~expected, 0) << "node " << i;
    }
}

TEST(SurfacePatches, HoleFlipAndDegenerateTriangleLeaveTheRootWithoutALoop) {
    MeshData holed = testing::grid_sheet(8, 8.0);
    holed.triangles.erase(holed.triangles.begin() + 70, holed.triangles.begin() + 72);  // one interior cell
    EXPECT_EQ(patched_tree(holed).patches.loop_size[0], 0u);
    expect_loops_match(patched_tree(holed));

    MeshData flipped = testing::grid_sheet(8, 8.0);
    std::swap(flipped.triangles[70][1], flipped.triangles[70][2]);
    EXPECT_EQ(patched_tree(flipped).patches.loop_size[0], 0u);

    MeshData degenerate = testing::grid_sheet(8, 8.0);
    degenerate.triangles[70][1] = degenerate.triangles[70][0];
    EXPECT_EQ(patched_tree(degenerate).patches.loop_size[0], 0u);
}

TEST(SurfacePatches, LoopsMatchTheReferenceOnCrumpledSheetsWithBothBuilders) {
    const std::uint64_t seed = 7;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uint32_t with_loop = 0;
    for (int round = 0; round < 6; ++round) {
        const MeshData mesh = testing::crumpled_sheet(rng, 10 + round, round % 2 ? 1.0 : 0.2, round % 3 == 0);
        for (const Builder builder : {Builder::Lbvh, Builder::Sah}) expect_loops_match(patched_tree(mesh, builder), &with_loop);
    }
    EXPECT_GT(with_loop, 100u);
}

TEST(SurfacePatches, ProvenEmbeddedNodesHaveNoCollidingPairs) {
    const double pi = 3.141592653589793;
    std::vector<std::pair<std::string, MeshData>> meshes;
    meshes.emplace_back("flat", testing::grid_sheet(16, 4.0));
    meshes.emplace_back("waved", testing::surface_grid(24, 24, [](double u, double v) {
        return Vec3(u, v, 0.05 * std::sin(9 * u) * std::cos(7 * v));
    }));
    // A sheet folded over onto itself along x = 0.5, exactly coplanar.
    meshes.emplace_back("folded", testing::surface_grid(16, 8, [](double u, double v) {
        return Vec3(u <= 0.5 ? u : 1 - u, v, 0);
    }));
    meshes.emplace_back("slit", testing::slit_sheet(12, 6));
    meshes.emplace_back("ramp-rising", testing::helix_ramp(1.5, [](double a) { return 0.2 * a; }));
    meshes.emplace_back("ramp-flat", testing::helix_ramp(1.5, [](double) { return 0.0; }));
    meshes.emplace_back("ramp-piercing", testing::helix_ramp(1.75, [](double a) { return 0.5 * std::sin(0.75 * a); }));
    // Pinched: a sheet whose row y = 0.5 is pushed along x onto its neighbour row's corners.
    meshes.emplace_back("pinched", testing::surface_grid(12, 12, [&](double u, double v) {
        return Vec3(u + (std::abs(v - 0.5) < 1e-9 && std::abs(u - 0.5) < 1e-9 ? 1.0 / 12 : 0.0), v, 0);
    }));
    const std::uint64_t seed = 11;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    for (int round = 0; round < 4; ++round)
        meshes.emplace_back("crumpled " + std::to_string(round), testing::crumpled_sheet(rng, 14, 0.25 * round, round % 2));
    (void)pi;
    for (const auto& [name, mesh] : meshes) {
        SCOPED_TRACE(name);
        for (const Builder builder : {Builder::Lbvh, Builder::Sah}) {
            const Tree tree = patched_tree(mesh, builder);
            expect_loops_match(tree);
            const std::uint32_t embedded = expect_embedded_sound(tree, mesh);
            std::printf("%s: %u of %zu nodes proven embedded, root %s\n", name.c_str(), embedded, tree.nodes.size(),
                        patch_is_embedded(tree, 0, mesh.vertices) ? "yes" : "no");
            if (name == "flat" || name == "waved") {
                EXPECT_TRUE(patch_is_embedded(tree, 0, mesh.vertices));
            }
            if (name.rfind("ramp", 0) == 0 || name == "folded" || name == "slit" || name == "pinched") {
                EXPECT_FALSE(patch_is_embedded(tree, 0, mesh.vertices));
            }
        }
    }
}

}  // namespace
}  // namespace collidescope::bvh
