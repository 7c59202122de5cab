// round_to_float32 and is_float32 (engine/src/geometry/float32.cpp), checked against values
// written in hexadecimal, so no conversion in this file can hide a wrong rounding. The
// generator pattern (three neighbouring round trips filling one Vec3) is the one GCC 12.2's
// SLP vectorizer miscompiled when it was written inline (docs/how-to/toolchain.md).

#include "support/random_triangles.hpp"

#include "collidescope/types.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace collidescope {
namespace {

TEST(Float32, RoundsToNearestWithTiesToEven) {
    EXPECT_EQ(round_to_float32(0.1), 0x1.99999ap-4);         // 0.1 = 0x1.999999999999ap-4
    EXPECT_EQ(round_to_float32(0.2), 0x1.99999ap-3);
    EXPECT_EQ(round_to_float32(-1.0 / 3.0), -0x1.555556p-2);
    EXPECT_EQ(round_to_float32(0x1.000001p0), 0x1.0p0);       // halfway: tie to even (down)
    EXPECT_EQ(round_to_float32(0x1.000003p0), 0x1.000004p0);  // halfway: tie to even (up)
    EXPECT_EQ(round_to_float32(0x1.0000010000001p0), 0x1.000002p0);  // just above halfway
    EXPECT_EQ(round_to_float32(1e-46), 0.0);                  // below the smallest subnormal
    EXPECT_EQ(round_to_float32(1e39), std::numeric_limits<double>::infinity());
}

TEST(Float32, NeighbouringRoundTripsInOneVectorAllRound) {
    // The miscompiled shape: Vec3(f(a), f(b), f(c)) from values that are not float32.
    const Vec3 r(round_to_float32(0.1), round_to_float32(0.2), round_to_float32(0.3));
    EXPECT_EQ(r, Vec3(0x1.99999ap-4, 0x1.99999ap-3, 0x1.333334p-2));
    EXPECT_EQ(round_to_float32(Vec3(0.1, 0.2, 0.3)), r);
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p(round_to_float32(unit(rng)), round_to_float32(unit(rng)), round_to_float32(unit(rng)));
        for (int k = 0; k < 3; ++k) {
            // A normal float32 has 24 significant bits: its significand (frexp, in [0.5, 1))
            // scaled by 2^24 is an integer; exact in double, whatever the vectorizer does.
            int exponent = 0;
            const double significand = std::ldexp(std::frexp(p[k], &exponent), 24);
            ASSERT_EQ(significand, std::floor(significand)) << std::hexfloat << p[k];
            ASSERT_TRUE(is_float32(p[k]));
        }
    }
}

TEST(Float32, IsFloat32) {
    EXPECT_TRUE(is_float32(0.5));
    EXPECT_TRUE(is_float32(0x1.99999ap-4));
    EXPECT_FALSE(is_float32(0.1));
    EXPECT_FALSE(is_float32(0x1.0000001p0));
}

// The test generators' float32 pairs ("crossing", not rescaled) really are float32.
TEST(Float32, TestGeneratorsMakeFloat32Coordinates) {
    std::mt19937_64 rng(7);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const testing::TrianglePairCase c = testing::random_near_contact_pair(rng);
        if (c.kind != "crossing") continue;
        ++checked;
        for (const auto* t : {&c.a, &c.b}) {
            for (const Vec3& p : *t) {
                for (int k = 0; k < 3; ++k) ASSERT_TRUE(is_float32(p[k])) << std::hexfloat << p[k];
            }
        }
    }
    EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace collidescope
