// Regions and curves against cases whose answer is known in closed form: two spheres (one
// loop, the circle's length, closer as the spheres are refined), a torus cut by a plane (two
// loops of known radii), coplanar patches (the overlap's area), a folded strip cutting itself
// (one open chain across its width); and degenerate input that must give regions, not crashes.

#include "support/scene_builders.hpp"

#include "collidescope/regions.hpp"
#include "regions/region_shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace collidescope {
namespace {

using namespace testing;

TEST(FindRegions, TwoSpheresCrossInOneLoopWhoseLengthConvergesToTheCircle) {
    const double radius = 1.0, distance = 1.1;
    const double circle = 2 * k_pi * std::sqrt(radius * radius - distance * distance / 4);
    double last_error = INFINITY;
    for (const std::uint32_t segments : {16u, 32u, 64u, 128u}) {
        const Frame frame = make_frame({sphere(segments, segments / 2, Vec3(0, 0, 0), radius),
                                        sphere(segments + 3, segments / 2 + 1, Vec3(distance, 0.01, 0.02), radius)});
        const std::vector<Region> regions = regions_of(frame, false);
        ASSERT_EQ(regions.size(), 1u) << segments;
        const Region& region = regions[0];
        ASSERT_EQ(region.curves.size(), 1u) << segments;
        EXPECT_TRUE(region.curves[0].closed) << segments;
        EXPECT_EQ(region.loops, 1u);
        EXPECT_NEAR(region.curves[0].length, region.curve_length, 1e-9);
        const double error = std::abs(region.curve_length - circle);
        std::printf("spheres %u segments: curve %.6f, circle %.6f, error %.2e\n", segments, region.curve_length, circle,
                    error);
        EXPECT_LT(error, last_error) << segments;
        last_error = error;
    }
    EXPECT_LT(last_error, 1e-3 * circle);
}

TEST(FindRegions, TorusCutByAPlaneGivesTwoLoopsOfTheKnownRadii) {
    const double R = 2.0, r = 0.5, z = 0.1;
    const Frame frame = make_frame({torus(192, 48, R, r), plane_at(z, 3.0, 60)});
    const std::vector<Region> regions = regions_of(frame, false);
    std::vector<double> lengths;
    std::uint32_t loops = 0;
    for (const Region& region : regions) {
        loops += region.loops;
        for (const IntersectionCurve& curve : region.curves) lengths.push_back(curve.length);
    }
    ASSERT_EQ(loops, 2u);
    ASSERT_EQ(lengths.size(), 2u);
    std::sort(lengths.begin(), lengths.end());
    const double s = std::sqrt(r * r - z * z);
    EXPECT_NEAR(lengths[0], 2 * k_pi * (R - s), 0.01 * 2 * k_pi * (R - s));
    EXPECT_NEAR(lengths[1], 2 * k_pi * (R + s), 0.01 * 2 * k_pi * (R + s));
}

// The degenerate form of the cut: the plane holds two of the torus's vertex rings, so the
// curves run along mesh edges lying in the other surface, each reported by the triangles on
// both of its sides. Every edge counts once: the loops are the rings' polygons.
TEST(FindRegions, PlaneThroughVertexRingsCountsEachEdgeOnce) {
    const double R = 2.0, r = 0.5;
    const std::uint32_t around = 96;
    const Frame frame = make_frame({torus(around, 24, R, r, 0.0), plane_at(0.0, 3.0, 40)});
    std::vector<double> lengths;
    for (const Region& region : regions_of(frame, false)) {
        for (const IntersectionCurve& curve : region.curves) {
            EXPECT_TRUE(curve.closed);
            lengths.push_back(curve.length);
        }
    }
    ASSERT_EQ(lengths.size(), 2u);
    std::sort(lengths.begin(), lengths.end());
    const double side = 2 * std::sin(k_pi / around);
    EXPECT_NEAR(lengths[0], around * side * (R - r), 1e-9);
    EXPECT_NEAR(lengths[1], around * side * (R + r), 1e-9);
}

TEST(FindRegions, CoplanarPatchesGiveTheOverlapArea) {
    const MeshData a = surface_grid(8, 8, [](double u, double v) { return Vec3(2 * u, 2 * v, 0); });
    const MeshData b = surface_grid(7, 9, [](double u, double v) { return Vec3(1 + 2 * u, 0.5 + 2 * v, 0); });
    const Frame frame = make_frame({a, b});
    const std::vector<Region> regions = regions_of(frame, false);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_NEAR(regions[0].coplanar_area, 1.0 * 1.5, 1e-12);
    EXPECT_DOUBLE_EQ(regions[0].box.min().x(), 1.0);
    EXPECT_DOUBLE_EQ(regions[0].box.max().y(), 2.0);
}

// A strip along a prolate cycloid, which loops over itself: the two crossing parts meet along
// a straight line across the strip's whole width (every cell is planar).
TEST(FindRegions, FoldedStripCutsItselfInOneOpenChainAcrossItsWidth) {
    const double width = 0.8;
    const MeshData strip = surface_grid(90, 5, [=](double u, double v) {
        const double t = -2.5 + 5.1 * u;
        return Vec3(t - 2 * std::sin(t), width * v, 1 - 2 * std::cos(t));
    });
    const Frame frame = make_frame({strip});
    const std::vector<Region> regions = regions_of(frame, true);
    ASSERT_EQ(regions.size(), 1u);
    const Region& region = regions[0];
    EXPECT_EQ(region.obj_a, 0u);
    EXPECT_EQ(region.obj_b, 0u);
    ASSERT_EQ(region.curves.size(), 1u);
    EXPECT_FALSE(region.curves[0].closed);
    EXPECT_NEAR(region.curve_length, width, 1e-9);
    EXPECT_NEAR(region.box.min().y(), 0.0, 1e-12);
    EXPECT_NEAR(region.box.max().y(), width, 1e-12);
}

// Degenerate contact: a torus whose vertex ring lies exactly in the plane, a zero-area
// triangle, a duplicated triangle: regions come back, finite, and nothing crashes.
TEST(FindRegions, DegenerateInputGivesFiniteRegions) {
    MeshData bad = torus(64, 16, 2.0, 0.5);
    bad.vertices.push_back(Vec3(2.0, 0, -1));
    bad.vertices.push_back(Vec3(2.0, 0, 1));
    bad.triangles.push_back({0, static_cast<std::uint32_t>(bad.vertices.size() - 2),
                             static_cast<std::uint32_t>(bad.vertices.size() - 1)});  // a sliver across the plane
    bad.triangles.push_back(bad.triangles.front());
    MeshData flat = torus(64, 16, 2.0, 0.5);
    for (Vec3& v : flat.vertices) v.z() = std::abs(v.z()) < 0.2 ? 0.0 : v.z();
    const Frame frame = make_frame({bad, plane_at(0.0, 3.0, 16), flat});
    const std::vector<Region> regions = regions_of(frame, true);
    ASSERT_FALSE(regions.empty());
    for (const Region& region : regions) {
        EXPECT_TRUE(std::isfinite(region.curve_length));
        EXPECT_TRUE(std::isfinite(region.coplanar_area));
        EXPECT_GT(region.pairs, 0u);
        for (const IntersectionCurve& curve : region.curves) {
            for (const Vec3& point : curve.points) EXPECT_TRUE(point.allFinite());
        }
    }
}

}  // namespace
}  // namespace collidescope

namespace collidescope {
namespace {

// The grouping against its definition, checked the slow way: two pairs of one object pair are
// in one region exactly when a chain of pairs, each sharing a vertex with the next on either
// side, joins them (every pair against every other, a flood).
TEST(FindRegions, RegionsAreTheClassesOfPairsSharingAVertexOnEitherSide) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
        const bool self = seed % 3 == 0;
        const Scene scene = testing::random_scene(seed, {.objects = 3, .frames = 1, .max_triangles = 60, .sheet_cells = 7});
        const Frame frame = testing::all_frames(scene)[0];
        const std::vector<TrianglePair> pairs = pairs_of(frame, self);
        const std::vector<Region> regions = find_regions(frame, pairs, {.curves = false, .penetration = false});
        std::vector<int> region_of(pairs.size(), -1);
        for (std::size_t r = 0; r < regions.size(); ++r) {
            for (const std::uint32_t i : regions[r].pair_indices) region_of[i] = static_cast<int>(r);
        }
        const auto shares = [&](const TrianglePair& x, const TrianglePair& y) {
            if (x.obj_a != y.obj_a || x.obj_b != y.obj_b) return false;
            const auto corners = [&](std::uint32_t object, std::uint32_t tri) { return frame.objects[object].topology->triangles[tri]; };
            // Self-contact: all four triangles are one object's, every corner against every corner.
            std::vector<std::uint32_t> cx, cy;
            for (const std::uint32_t v : corners(x.obj_a, x.tri_a)) cx.push_back(v);
            for (const std::uint32_t v : corners(y.obj_a, y.tri_a)) cy.push_back(v);
            const bool self_pair = x.obj_a == x.obj_b;
            std::vector<std::uint32_t> bx, by;
            for (const std::uint32_t v : corners(x.obj_b, x.tri_b)) (self_pair ? cx : bx).push_back(v);
            for (const std::uint32_t v : corners(y.obj_b, y.tri_b)) (self_pair ? cy : by).push_back(v);
            for (const std::uint32_t u : cx) {
                for (const std::uint32_t v : cy) {
                    if (u == v) return true;
                }
            }
            for (const std::uint32_t u : bx) {
                for (const std::uint32_t v : by) {
                    if (u == v) return true;
                }
            }
            return false;
        };
        std::vector<int> slow(pairs.size(), -1);
        int classes = 0;
        for (std::size_t start = 0; start < pairs.size(); ++start) {
            if (slow[start] >= 0) continue;
            std::vector<std::size_t> queue{start};
            slow[start] = classes;
            for (std::size_t next = 0; next < queue.size(); ++next) {
                for (std::size_t j = 0; j < pairs.size(); ++j) {
                    if (slow[j] < 0 && shares(pairs[queue[next]], pairs[j])) {
                        slow[j] = classes;
                        queue.push_back(j);
                    }
                }
            }
            ++classes;
        }
        ASSERT_EQ(regions.size(), static_cast<std::size_t>(classes)) << "seed " << seed;
        // The same partition: classes numbered by first pair on both sides.
        for (std::size_t i = 0; i < pairs.size(); ++i) ASSERT_EQ(region_of[i], slow[i]) << "seed " << seed << " pair " << i;
        std::printf("  %zu pairs, %d regions\n", pairs.size(), classes);
    }
}

}  // namespace
}  // namespace collidescope
