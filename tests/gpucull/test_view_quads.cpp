// The conservative per-triangle records (view_quads): over every pixel a triangle touches, its
// depths lie within the record's bounds, checked in double on seeded random triangles,
// slivers and edge-on triangles, at points sampled inside each pixel.

#include "gpucull/view_quads.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace collidescope::gpucull {
namespace {

constexpr std::uint64_t k_seed = 20261122;

// Depth and pixel coordinates of a point in the view, in double, as make_quad defines them.
struct Point {
    double x, y, z;
};

Point project(const View& view, const Vec3& p) {
    const int u = (view.axis + 1) % 3, v = (view.axis + 2) % 3, d = view.axis;
    const Vec3 lo = view.bounds.min();
    const Vec3 e = view.bounds.max() - lo;
    return {(p[u] - lo[u]) * view.width / e[u], (p[v] - lo[v]) * view.height / e[v], 0.25 + (p[d] - lo[d]) * 0.5 / e[d]};
}

Vec3 random_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    return {coordinate(rng), coordinate(rng), coordinate(rng)};
}

// A triangle: general, a sliver (two corners nearly equal), or seen nearly edge-on.
std::array<Vec3, 3> random_triangle(std::mt19937_64& rng, int kind, int axis) {
    const Vec3 a = random_point(rng);
    Vec3 b = random_point(rng);
    Vec3 c = random_point(rng);
    std::uniform_real_distribution<double> tiny(-1e-9, 1e-9);
    if (kind == 1) c = b + Vec3(tiny(rng), tiny(rng), tiny(rng));
    if (kind == 2) {  // in a plane containing the view axis, up to a hair
        const int u = (axis + 1) % 3;
        b[u] = a[u] + tiny(rng);
        c[u] = a[u] + tiny(rng);
    }
    return {a, b, c};
}

TEST(ViewQuads, BoundsHoldAtEveryPointOfTheTriangle) {
    std::mt19937_64 rng(k_seed);
    std::cout << "[ seed     ] " << k_seed << '\n';
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int axis = trial % 3;
        const int size = trial % 2 == 0 ? 512 : 8;
        View view{axis, Eigen::AlignedBox3d(Vec3(0, 0, 0), Vec3(1, 1, 1)), size, size};
        const std::array<Vec3, 3> t = random_triangle(rng, trial % 3, axis);
        const TriangleQuad quad = make_quad(view, t[0], t[1], t[2], 0);
        for (int sample = 0; sample < 20; ++sample) {
            double w0 = unit(rng), w1 = unit(rng);
            if (w0 + w1 > 1) { w0 = 1 - w0; w1 = 1 - w1; }
            const Vec3 p = t[0] + w0 * (t[1] - t[0]) + w1 * (t[2] - t[0]);
            const Point q = project(view, p);
            const double px = std::floor(q.x) + 0.5, py = std::floor(q.y) + 0.5;
            ASSERT_TRUE(quad_covers(quad, px, py)) << "trial " << trial;
            ASSERT_GE(quad_depth_bound(quad, px, py, true), q.z) << "trial " << trial;
            ASSERT_LE(quad_depth_bound(quad, px, py, false), q.z) << "trial " << trial;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 60000);
}

// Coverage is the pixels the triangle touches (up to the margin), not its whole box: a thin
// diagonal triangle leaves most of its box's pixels alone.
TEST(ViewQuads, CoverageFollowsTheTriangleNotItsBox) {
    const View view{2, Eigen::AlignedBox3d(Vec3(0, 0, 0), Vec3(1, 1, 1)), 64, 64};
    const TriangleQuad quad = make_quad(view, Vec3(0, 0, 0.5), Vec3(1, 1, 0.5), Vec3(1, 0.98, 0.5), 0);
    int covered = 0, boxed = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            boxed += 1;
            covered += quad_covers(quad, x + 0.5, y + 0.5) ? 1 : 0;
        }
    }
    EXPECT_LT(covered, boxed / 8);
    EXPECT_GE(covered, 64);  // at least the diagonal
}

// The bounds are tight enough to be useful: a triangle facing the view has a per-pixel spread
// far below its depth range (otherwise nothing would ever be culled).
TEST(ViewQuads, FacingTrianglesGetTightPerPixelBounds) {
    const View view{2, Eigen::AlignedBox3d(Vec3(0, 0, 0), Vec3(1, 1, 1)), 512, 512};
    const TriangleQuad quad = make_quad(view, Vec3(0.1, 0.1, 0.2), Vec3(0.9, 0.1, 0.6), Vec3(0.1, 0.9, 0.2), 7);
    EXPECT_EQ(quad.id, 7u);
    const double upper = quad_depth_bound(quad, 256.5, 100.5, true);
    const double lower = quad_depth_bound(quad, 256.5, 100.5, false);
    EXPECT_LT(upper - lower, 0.01 * (quad.zhi - quad.zlo));
}

}  // namespace
}  // namespace collidescope::gpucull
