// intersect_pair on random pairs biased toward contact (grazing, coplanar, on-a-grid, nearly
// degenerate): every point it returns lies on both triangles, within rounding of the
// coordinates; a coplanar overlap's area is at most either triangle's.

#include "support/random_triangles.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/geometry.hpp"
#include "collidescope/regions.hpp"
#include "regions/pair_intersection.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace collidescope {
namespace {

// The distance from p to the closed triangle (a, b, c) (Ericson, Real-Time Collision
// Detection, 5.1.5), for triangles of non-zero area.
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return (p - a).norm();
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return (p - b).norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return (p - c).norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
    const double denominator = 1 / (va + vb + vc);
    return (p - (a + ab * vb * denominator + ac * vc * denominator)).norm();
}

double area(const std::array<Vec3, 3>& t) { return 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm(); }

TEST(PairIntersection, EveryPointLiesOnBothTrianglesOnRandomContactPairs) {
    const std::uint64_t seed = 20261127;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uint32_t tested = 0, segments = 0, polygons = 0;
    for (int i = 0; i < 20000; ++i) {
        const testing::TrianglePairCase c = testing::random_near_contact_pair(rng);
        if (!triangles_intersect(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2])) continue;
        const Frame frame = testing::make_frame({MeshData{{c.a.begin(), c.a.end()}, {{0, 1, 2}}},
                                                 MeshData{{c.b.begin(), c.b.end()}, {{0, 1, 2}}}});
        const PairIntersection cut = intersect_pair(frame, {0, 0, 1, 0});
        ASSERT_FALSE(cut.points.empty()) << testing::describe(c.a, c.b);
        for (const Vec3& p : cut.points) ASSERT_TRUE(p.allFinite()) << testing::describe(c.a, c.b);
        ++tested;
        segments += cut.kind == PairIntersection::Kind::Segment;
        polygons += cut.kind == PairIntersection::Kind::Polygon;
        if (area(c.a) == 0 || area(c.b) == 0) continue;  // a segment or point: no distance to a face
        double scale = 1;
        for (const Vec3& v : c.a) scale = std::max(scale, v.cwiseAbs().maxCoeff());
        for (const Vec3& v : c.b) scale = std::max(scale, v.cwiseAbs().maxCoeff());
        const double tolerance = 1e-9 * scale;
        for (const Vec3& p : cut.points) {
            EXPECT_LE(distance_to_triangle(p, c.a[0], c.a[1], c.a[2]), tolerance) << int(cut.kind) << " n=" << cut.points.size() << " p=" << p.transpose() << " " << c.kind << ' ' << testing::describe(c.a, c.b);
            EXPECT_LE(distance_to_triangle(p, c.b[0], c.b[1], c.b[2]), tolerance) << c.kind << ' ' << testing::describe(c.a, c.b);
        }
        if (cut.kind == PairIntersection::Kind::Polygon) {
            EXPECT_LE(cut.area, std::min(area(c.a), area(c.b)) * (1 + 1e-9)) << testing::describe(c.a, c.b);
        }
    }
    std::printf("%u intersecting pairs: %u segments, %u coplanar polygons\n", tested, segments, polygons);
    EXPECT_GT(segments, 1000u);
    EXPECT_GT(polygons, 100u);
}

// The generic fast path (four edge-edge orientations) against the general path (every end
// located on the other triangle) on random crossing pairs: the same ends, the same keys.
TEST(PairIntersection, FastPathEqualsTheGeneralPath) {
    const std::uint64_t seed = 38;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    const auto random_triangle = [&] {
        std::vector<Vec3> corners;
        for (int k = 0; k < 3; ++k) corners.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
        return corners;
    };
    std::uint32_t compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const std::vector<Vec3> a = random_triangle(), b = random_triangle();
        if (!triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) continue;
        const Frame frame = testing::make_frame({MeshData{a, {{0, 1, 2}}}, MeshData{b, {{0, 1, 2}}}});
        const regions::Piece fast = regions::intersect(frame, {0, 0, 1, 0}, nullptr, true);
        const regions::Piece general = regions::intersect(frame, {0, 0, 1, 0}, nullptr, false);
        ASSERT_EQ(fast.kind, general.kind) << i;
        if (fast.kind != PairIntersection::Kind::Segment) continue;
        // The same two ends, in either order.
        const bool swapped = !(fast.keys[0] == general.keys[0]);
        const int f0 = swapped ? 1 : 0;
        EXPECT_TRUE(fast.keys[f0] == general.keys[0] && fast.keys[1 - f0] == general.keys[1]) << i;
        EXPECT_LE((fast.ends[f0] - general.ends[0]).norm(), 1e-12) << i;
        EXPECT_LE((fast.ends[1 - f0] - general.ends[1]).norm(), 1e-12) << i;
        ++compared;
    }
    std::printf("%u crossing pairs compared\n", compared);
    EXPECT_GT(compared, 1000u);
}

}  // namespace
}  // namespace collidescope

namespace collidescope {
namespace {

// plane_sides' shortcut for planes whose corners share a coordinate against orient3d, on small
// integer grids (many corners exactly in the plane), every axis and both turns of the plane.
TEST(PairIntersection, AxisAlignedPlaneSidesEqualOrient3d) {
    const std::uint64_t seed = 38;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> grid(-3, 3);
    std::uint32_t zeros = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const int axis = i % 3;
        const double level = grid(rng) * 0.25;
        std::array<Vec3, 3> plane, t;
        for (Vec3& p : plane) {
            p = Vec3(grid(rng), grid(rng), grid(rng)) * 0.5;
            p[axis] = level;
        }
        for (Vec3& p : t) p = Vec3(grid(rng), grid(rng), grid(rng)) * 0.25;
        const std::array<int, 3> fast = regions::plane_sides(plane, t, true);
        const std::array<int, 3> slow = regions::plane_sides(plane, t, false);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(fast[k], slow[k]) << "case " << i << " axis " << axis << " corner " << k;
            ASSERT_EQ(slow[k], orient3d(plane[0], plane[1], plane[2], t[k]));
            zeros += slow[k] == 0;
            ++checked;
        }
    }
    std::printf("%u signs, %u zero\n", checked, zeros);
    EXPECT_GT(zeros, 1000u);
}

// Triangles in one axis-aligned plane (exact: a shared coordinate) are clipped in 2D; the
// general path clips in 3D after six plane sides. The same kind, area and box, on small grids
// (edges through corners, shared corners, flat triangles) in each axis plane.
TEST(PairIntersection, AxisPlaneClipEqualsTheGeneralClip) {
    const std::uint64_t seed = 3801;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> grid(-4, 4);
    std::uint32_t polygons = 0, compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const int axis = i % 3;
        const double level = grid(rng) * 0.375;
        std::vector<Vec3> a(3), b(3);
        for (std::vector<Vec3>* t : {&a, &b}) {
            for (Vec3& p : *t) {
                p = Vec3(grid(rng), grid(rng), grid(rng)) * 0.25;
                p[axis] = level;
            }
        }
        if (!triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) continue;
        const Frame frame = testing::make_frame({MeshData{a, {{0, 1, 2}}}, MeshData{b, {{0, 1, 2}}}});
        std::vector<Vec3> fast_points, general_points;
        const regions::Piece fast = regions::intersect(frame, {0, 0, 1, 0}, &fast_points, true);
        const regions::Piece general = regions::intersect(frame, {0, 0, 1, 0}, &general_points, false);
        const bool flat = (a[1] - a[0]).cross(a[2] - a[0]).squaredNorm() == 0 || (b[1] - b[0]).cross(b[2] - b[0]).squaredNorm() == 0;
        for (const Vec3& p : fast_points) ASSERT_EQ(p[axis], level) << "case " << i;
        if (flat) continue;  // the general path projects a flat pair along another axis
        ASSERT_EQ(fast.kind, general.kind) << "case " << i;
        ASSERT_EQ(fast_points.size(), general_points.size()) << "case " << i;
        EXPECT_NEAR(fast.area, general.area, 1e-12) << "case " << i;
        for (int k = 0; k < 2; ++k) EXPECT_LE((fast.ends[k] - general.ends[k]).norm(), 1e-12) << "case " << i;
        polygons += fast.kind == PairIntersection::Kind::Polygon;
        ++compared;
    }
    std::printf("%u coplanar pairs compared, %u polygons\n", compared, polygons);
    EXPECT_GT(polygons, 1000u);
}

}  // namespace
}  // namespace collidescope
