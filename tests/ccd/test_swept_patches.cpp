// The swept patch test against the per-frame one sampled over the interval: what it proves for
// every time must hold at every sampled time (random triangles and loops, seeds printed), a
// loop that is simple at both ends but not in between is not proven, and plain motions are.

#include "ccd/swept_patches.hpp"
#include "geometry/simple_loop.hpp"
#include "support/sweep_size.hpp"

#include "collidescope/geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace collidescope::ccd {
namespace {

constexpr int k_samples = 64;  // times k / 64 checked, both ends included

std::vector<Vec3> at_time(const std::vector<Vec3>& from, const std::vector<Vec3>& to, double t) {
    std::vector<Vec3> positions(from.size());
    for (std::size_t k = 0; k < from.size(); ++k) positions[k] = (1 - t) * from[k] + t * to[k];
    return positions;
}

TEST(SweptPatches, TriangleSidesHoldWhileTheProjectedOrientationKeepsItsSign) {
    const TriIndices t{0, 1, 2};
    const std::vector<Vec3> from{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    // Moved along z and x: counterclockwise seen down z throughout (bit 4 of axis 2); edge-on
    // to x and y (no bit).
    const std::vector<Vec3> moved{{0.5, 0, 2}, {1.5, 0, 2}, {0.5, 1, 2}};
    EXPECT_EQ(swept_triangle_sides(t, from, moved), 1u << 4);
    // Corner 2 crosses the line of edge 01: the orientation changes sign, nothing is proven.
    const std::vector<Vec3> flipped{{0, 0, 0}, {1, 0, 0}, {0, -1, 0}};
    EXPECT_EQ(swept_triangle_sides(t, from, flipped) & (3u << 4), 0u);
    // Far from the origin, the same motion keeps its bit.
    std::vector<Vec3> far_from = from, far_to = moved;
    for (Vec3& p : far_from) p += Vec3(1e6, -1e6, 1e6);
    for (Vec3& p : far_to) p += Vec3(1e6, -1e6, 1e6);
    EXPECT_EQ(swept_triangle_sides(t, far_from, far_to), 1u << 4);
}

TEST(SweptPatches, TriangleSidesProvenHoldAtEverySampledTime) {
    int proven = 0, checked = 0;
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({21, 22, 23, 24})) {
        std::printf("[ seed     ] SweptPatches triangles: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> coordinate(-1, 1), scale(0, 1.5);
        for (int n = 0; n < 2000; ++n) {
            std::vector<Vec3> from(3), to(3);
            const double move = scale(rng);
            for (int k = 0; k < 3; ++k) {
                from[k] = {coordinate(rng), coordinate(rng), coordinate(rng)};
                to[k] = from[k] + move * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
            }
            const std::uint8_t bits = swept_triangle_sides({0, 1, 2}, from, to);
            for (int drop = 0; drop < 3; ++drop) {
                const unsigned side = (bits >> (2 * drop)) & 3u;
                if (side == 0) continue;
                ASSERT_NE(side, 3u);
                ++proven;
                for (int s = 0; s <= k_samples; ++s) {
                    const std::vector<Vec3> p = at_time(from, to, static_cast<double>(s) / k_samples);
                    ++checked;
                    ASSERT_EQ(orient2d(p[0], p[1], p[2], drop), side == 1 ? 1 : -1)
                        << "seed " << seed << " triangle " << n << " axis " << drop << " time " << s << "/" << k_samples;
                }
            }
        }
    }
    std::printf("%d orientations proven, %d sampled times checked\n", proven, checked);
    EXPECT_GT(proven, 0);
}

// A square whose corner 2 moves straight across the square and out past corner 0: simple at
// both ends (a convex square, then an arrow), but corner 2 passes through corner 0 at t = 1/2.
TEST(SweptPatches, ALoopSimpleAtBothEndsButNotBetweenIsNotProven) {
    const std::vector<std::uint32_t> loop{0, 1, 2, 3};
    const std::vector<Vec3> from{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<Vec3> to = from;
    to[2] = {-1, -1, 0};
    ASSERT_TRUE(contact::projected_loop_is_simple_reference(loop, from, 2));
    ASSERT_TRUE(contact::projected_loop_is_simple_reference(loop, to, 2));
    ASSERT_FALSE(contact::projected_loop_is_simple_reference(loop, at_time(from, to, 0.5), 2));
    EXPECT_FALSE(swept_loop_stays_simple(loop, from, to, 2));
    // Moved as a whole, or squeezed a little, it stays simple and is proven so.
    std::vector<Vec3> shifted = from, squeezed = from;
    for (Vec3& p : shifted) p += Vec3(3, -2, 1);
    squeezed[2] = {0.8, 0.7, 0.1};
    EXPECT_TRUE(swept_loop_stays_simple(loop, from, shifted, 2));
    EXPECT_TRUE(swept_loop_stays_simple(loop, from, squeezed, 2));
    // A border of collinear edges (a sheet's straight side), moved: its edges part only along
    // their own direction.
    const std::vector<std::uint32_t> strip{0, 1, 2, 3, 4, 5};
    const std::vector<Vec3> start{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}};
    std::vector<Vec3> slid = start;
    for (Vec3& p : slid) p += Vec3(0.4, 0.3, 0);
    EXPECT_TRUE(swept_loop_stays_simple(strip, start, slid, 2));
    // Edge-on to the projection (dropping x, the square is a segment): not simple, not proven.
    EXPECT_FALSE(swept_loop_stays_simple(loop, from, shifted, 0));
}

// Random star-shaped loops (simple at t = 0), each corner moved by up to `move` times the
// loop's radius: a loop proven simple is simple at every sampled time.
TEST(SweptPatches, LoopsProvenSimpleAreSimpleAtEverySampledTime) {
    int proven = 0, refused = 0;
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({31, 32, 33, 34})) {
        std::printf("[ seed     ] SweptPatches loops: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
        for (int n = 0; n < 300; ++n) {
            const auto corners = static_cast<std::uint32_t>(3 + rng() % 40);
            std::vector<double> angles(corners);
            for (double& a : angles) a = 2 * std::numbers::pi * unit(rng);
            std::sort(angles.begin(), angles.end());
            std::vector<Vec3> from(corners), to(corners);
            std::vector<std::uint32_t> loop(corners);
            const double move = std::array{0.02, 0.1, 0.3, 1.0}[rng() % 4];
            for (std::uint32_t k = 0; k < corners; ++k) {
                const double radius = 0.3 + 0.7 * unit(rng);
                from[k] = {radius * std::cos(angles[k]), radius * std::sin(angles[k]), 0.1 * signed_unit(rng)};
                to[k] = from[k] + move * Vec3(signed_unit(rng), signed_unit(rng), signed_unit(rng));
                loop[k] = k;
            }
            if (!swept_loop_stays_simple(loop, from, to, 2)) {
                ++refused;
                continue;
            }
            ++proven;
            for (int s = 0; s <= k_samples; ++s) {
                ASSERT_TRUE(contact::projected_loop_is_simple_reference(loop, at_time(from, to, static_cast<double>(s) / k_samples), 2))
                    << "seed " << seed << " loop " << n << " time " << s << "/" << k_samples;
            }
        }
    }
    std::printf("%d loops proven simple throughout, %d not proven\n", proven, refused);
    EXPECT_GT(proven, 0);
    EXPECT_GT(refused, 0);
}

// Still loops of four corners at scales from 1e-300 to 1e155 (past the engine's limit of 1e100,
// where products overflow): a loop proven simple is simple by the exact per-frame test. A
// review found the separating directions' products overflowing at 1e154 and proving loops that
// cross themselves.
TEST(SweptPatches, StillLoopsProvenSimpleAreSimpleAtEveryScale) {
    const std::vector<std::uint32_t> loop{0, 1, 2, 3};
    int proven = 0;
    for (const double scale : {1e-300, 1e-162, 1.0, 1e99, 1.5e154, 1e155}) {
        std::printf("[ seed     ] SweptPatches still loops: seed 51, scale %g\n", scale);
        std::mt19937_64 rng(51);
        std::uniform_real_distribution<double> coordinate(-1, 1);
        for (int n = 0; n < 20000; ++n) {
            std::vector<Vec3> corners(4);
            for (Vec3& p : corners) p = Vec3(scale * coordinate(rng), scale * coordinate(rng), 0);
            if (!swept_loop_stays_simple(loop, corners, corners, 2)) continue;
            ++proven;
            ASSERT_TRUE(contact::projected_loop_is_simple(loop, corners, 2)) << "scale " << scale << " loop " << n;
        }
    }
    std::printf("%d loops proven simple\n", proven);
    EXPECT_GT(proven, 1000);
}

}  // namespace
}  // namespace collidescope::ccd
