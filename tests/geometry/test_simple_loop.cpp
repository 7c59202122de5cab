// projected_loop_is_simple against its all-pairs reference on random polygons snapped to a
// coarse grid (collinear runs, touching corners, folds back, repeated points), short ones and
// long ones (the grid path), in each projection; and hand-made cases.

#include "geometry/simple_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

namespace collidescope::contact {
namespace {

std::vector<std::uint32_t> iota_loop(std::size_t n) {
    std::vector<std::uint32_t> loop(n);
    std::iota(loop.begin(), loop.end(), 0u);
    return loop;
}

/// Points (x, y) placed in the plane that drops `drop`, with `other` on the dropped axis.
std::vector<Vec3> in_plane(const std::vector<std::array<double, 2>>& points, int drop, double other = 0.5) {
    std::vector<Vec3> out;
    for (const auto& p : points) {
        Vec3 v;
        v[drop] = other;
        v[(drop + 1) % 3] = p[0];
        v[(drop + 2) % 3] = p[1];
        out.push_back(v);
    }
    return out;
}

bool simple(const std::vector<std::array<double, 2>>& points, int drop = 2) {
    const std::vector<Vec3> vertices = in_plane(points, drop);
    const auto loop = iota_loop(points.size());
    const bool fast = projected_loop_is_simple(loop, vertices, drop);
    EXPECT_EQ(fast, projected_loop_is_simple_reference(loop, vertices, drop));
    return fast;
}

TEST(SimpleLoop, HandMadeCases) {
    EXPECT_TRUE(simple({{0, 0}, {1, 0}, {0, 1}}));
    EXPECT_TRUE(simple({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_TRUE(simple({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}));  // a straight corner is fine
    EXPECT_FALSE(simple({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));         // a bow tie
    EXPECT_FALSE(simple({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));         // folds back along an edge
    EXPECT_FALSE(simple({{0, 0}, {1, 0}, {1, 0}, {0, 1}}));         // an edge of zero length
    EXPECT_FALSE(simple({{0, 0}, {1, 0}, {2, 0}}));                 // flat: folds back at the close
    EXPECT_FALSE(simple({{0, 0}, {1, 0}}));                         // too short
    // Two corners at one point (a pinch), and a corner touching another edge.
    EXPECT_FALSE(simple({{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}));
    EXPECT_FALSE(simple({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}));
    // The same in every projection.
    for (const int drop : {0, 1, 2}) {
        EXPECT_TRUE(simple({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, drop));
        EXPECT_FALSE(simple({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, drop));
    }
}

TEST(SimpleLoop, LongCircleAndOneTouch) {
    std::vector<std::array<double, 2>> circle;
    for (int k = 0; k < 1000; ++k) {
        const double a = 2 * 3.141592653589793 * k / 1000;
        circle.push_back({std::cos(a), std::sin(a)});
    }
    EXPECT_TRUE(simple(circle));
    // A corner pulled onto the far side of the circle touches it.
    std::vector<std::array<double, 2>> touched = circle;
    touched[250] = circle[750];
    EXPECT_FALSE(simple(touched));
    // A star with one spike crossing its neighbour.
    std::vector<std::array<double, 2>> star;
    for (int k = 0; k < 400; ++k) {
        const double a = 2 * 3.141592653589793 * k / 400, r = k % 2 ? 1.0 : 2.0;
        star.push_back({r * std::cos(a), r * std::sin(a)});
    }
    EXPECT_TRUE(simple(star));
    star[100] = {star[103][0] * 1.5, star[103][1] * 1.5};
    EXPECT_FALSE(simple(star));
}

TEST(SimpleLoop, RandomSnappedPolygonsMatchTheReference) {
    const std::uint64_t seed = 23;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    int simple_count = 0, total = 0;
    for (int round = 0; round < 3000; ++round) {
        // Star-shaped walks around a centre, radii and angles snapped, so many are simple and
        // many nearly so (collinear runs, touching corners).
        const std::size_t n = round % 3 == 0 ? 3 + rng() % 8 : (round % 3 == 1 ? 20 + rng() % 40 : 60 + rng() % 300);
        const int grid = 4 + static_cast<int>(rng() % 12);
        std::vector<std::array<double, 2>> points;
        for (std::size_t k = 0; k < n; ++k) {
            const double angle = 2 * 3.141592653589793 * (static_cast<double>(k) + static_cast<double>(rng() % 3) * 0.4) / static_cast<double>(n);
            const double radius = 1 + static_cast<double>(rng() % 8) * 0.25;
            points.push_back({std::round(grid * radius * std::cos(angle)) / grid,
                              std::round(grid * radius * std::sin(angle)) / grid});
        }
        if (rng() % 4 == 0) points[rng() % n] = points[rng() % n];  // a repeated point
        const int drop = static_cast<int>(rng() % 3);
        const std::vector<Vec3> vertices = in_plane(points, drop, static_cast<double>(rng() % 5));
        const auto loop = iota_loop(n);
        const bool fast = projected_loop_is_simple(loop, vertices, drop);
        ASSERT_EQ(fast, projected_loop_is_simple_reference(loop, vertices, drop)) << "round " << round;
        simple_count += fast;
        ++total;
    }
    std::printf("%d of %d simple\n", simple_count, total);
    EXPECT_GT(simple_count, total / 10);  // both answers are exercised
    EXPECT_LT(simple_count, total * 9 / 10);
}

}  // namespace
}  // namespace collidescope::contact
