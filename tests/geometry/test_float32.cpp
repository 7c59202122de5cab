// round_to_float32, is_float32, float32_below and float32_above (engine/src/geometry/float32.cpp),
// checked against values written in hexadecimal, so no conversion in this file can hide a wrong
// rounding. The generator pattern (three neighbouring round trips filling one Vec3) is the one
// GCC 12.2's SLP vectorizer miscompiled when it was written inline (docs/how-to/toolchain.md).

#include "support/random_triangles.hpp"

#include "collidescope/types.hpp"
#include "geometry/float32.hpp"

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

TEST(Float32, BelowAndAboveAreTheFloatsOnEachSide) {
    // The shape GCC 12.2 miscompiled inline: neighbouring round trips filling one struct.
    struct Bounds {
        double lo[3], hi[3];
    };
    const Bounds b{{float32_below(0.1), float32_below(0.2), float32_below(-0.3)},
                   {float32_above(0.1), float32_above(0.2), float32_above(-0.3)}};
    EXPECT_EQ(b.lo[0], 0x1.999998p-4);  // 0.1 = 0x1.999999999999ap-4: nearest 0x1.99999ap-4 is above
    EXPECT_EQ(b.hi[0], 0x1.99999ap-4);
    EXPECT_EQ(b.lo[1], 0x1.999998p-3);
    EXPECT_EQ(b.hi[1], 0x1.99999ap-3);
    EXPECT_EQ(b.lo[2], -0x1.333334p-2);  // -0.3 = -0x1.3333333333333p-2
    EXPECT_EQ(b.hi[2], -0x1.333332p-2);
    // A float32 is its own bound on both sides; zero's sign is kept.
    EXPECT_EQ(float32_below(0x1.99999ap-4), 0x1.99999ap-4);
    EXPECT_EQ(float32_above(-0.5), -0.5);
    EXPECT_EQ(float32_below(0.0), 0.0);
    EXPECT_FALSE(std::signbit(float32_below(0.0)));
    EXPECT_TRUE(std::signbit(float32_above(-0.0)));
    // Below the smallest subnormal, past the largest float, infinities and NaN.
    EXPECT_EQ(float32_below(1e-50), 0.0);
    EXPECT_EQ(float32_above(1e-50), 0x1.0p-149);
    EXPECT_EQ(float32_below(-1e-50), -0x1.0p-149);
    EXPECT_EQ(float32_above(-1e-50), 0.0);
    EXPECT_TRUE(std::signbit(float32_above(-1e-50)));  // -0: the nearest float keeps the sign
    EXPECT_EQ(float32_below(1e300), 0x1.fffffep127);
    EXPECT_EQ(float32_above(1e300), std::numeric_limits<double>::infinity());
    EXPECT_EQ(float32_below(-1e300), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(float32_above(-1e300), -0x1.fffffep127);
    EXPECT_EQ(float32_below(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
    EXPECT_EQ(float32_above(-std::numeric_limits<double>::infinity()), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(float32_below(std::nan(""))));
    EXPECT_TRUE(std::isnan(float32_above(std::nan(""))));
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
