// orient3d / orient2d against GMP rationals on random, near-degenerate and badly scaled
// inputs, and the filter's fallback counter.

#include "collidescope/geometry.hpp"
#include "geometry/adjacent_filter.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace collidescope {
namespace {

int reference_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    mpq_class m[3][3];
    const Vec3* rows[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) m[i][k] = mpq_class((*rows[i])[k]) - mpq_class(d[k]);
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sgn(det);
}

int reference_orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const mpq_class det = (mpq_class(a[i]) - c[i]) * (mpq_class(b[j]) - c[j]) -
                          (mpq_class(a[j]) - c[j]) * (mpq_class(b[i]) - c[i]);
    return sgn(det);
}

/// Points nearly on a plane/line: the float determinant is useless, the exact path decides.
TEST(Predicates, MatchRationalsOnNearDegenerateInputs) {
    const std::uint64_t seed = 20261122;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-60, 60);
    int zeros = 0, nonzeros = 0;
    for (int n = 0; n < 20000; ++n) {
        const double scale = std::ldexp(1.0, exponent(rng) * (n % 4 == 0 ? 4 : 1));
        const Vec3 a = Vec3(unit(rng), unit(rng), unit(rng)) * scale;
        const Vec3 b = Vec3(unit(rng), unit(rng), unit(rng)) * scale;
        const Vec3 c = Vec3(unit(rng), unit(rng), unit(rng)) * scale;
        // d on the plane in exact arithmetic when the weights are small dyadics, else nearly.
        const double u = std::ldexp(std::floor(unit(rng) * 8), -3);
        const double v = std::ldexp(std::floor(unit(rng) * 8), -3);
        const Vec3 d = a + u * (b - a) + v * (c - a);
        const int expected = reference_orient3d(a, b, c, d);
        ASSERT_EQ(orient3d(a, b, c, d), expected) << "seed " << seed << " case " << n;
        (expected == 0 ? zeros : nonzeros)++;
        for (int drop = 0; drop < 3; ++drop)
            ASSERT_EQ(orient2d(a, b, d, drop), reference_orient2d(a, b, d, drop))
                << "seed " << seed << " case " << n;
    }
    EXPECT_GT(zeros, 100);
    EXPECT_GT(nonzeros, 100);
}

TEST(Predicates, ExtremeMagnitudesUseExactArithmetic) {
    for (double scale : {1e-300, 0x1p-600, 1e-30, 1e30, 0x1p600, 1e300}) {
        const Vec3 a(0, 0, 0), b(scale, 0, 0), c(0, scale, 0);
        EXPECT_EQ(orient3d(a, b, c, Vec3(scale, scale, 0)), 0) << scale;
        EXPECT_EQ(orient3d(a, b, c, Vec3(0.25 * scale, 0.25 * scale, -scale)),
                  reference_orient3d(a, b, c, Vec3(0.25 * scale, 0.25 * scale, -scale)));
        const Vec3 tiny_up(0.3 * scale, 0.3 * scale, std::nextafter(0.0, 1.0));
        EXPECT_EQ(orient3d(a, b, c, tiny_up), reference_orient3d(a, b, c, tiny_up)) << scale;
        EXPECT_NE(orient3d(a, b, c, tiny_up), 0) << scale;
    }
}

TEST(Predicates, MixedMagnitudes) {
    // 1e30 and 1e-30 in one determinant: differences are inexact in doubles.
    const Vec3 a(1e30, 0, 0), b(1e30, 1e-30, 0), c(1e30, 0, 1e-30), d(1e30 + 1e15, 1e-30, 1e-30);
    EXPECT_EQ(orient3d(a, b, c, d), reference_orient3d(a, b, c, d));
    EXPECT_EQ(orient2d(a, b, d, 2), reference_orient2d(a, b, d, 2));
}

/// Extrusions (a tube's side meshed ring by ring, a wall): four points over two points of an
/// axis-aligned projection are coplanar, decided by the shortcut without the exact path; and
/// near-extrusions (one coordinate off by an ulp) keep their exact nonzero sign.
TEST(Predicates, ExtrusionsAreCoplanarWithoutTheExactPath) {
    const std::uint64_t seed = 20261127;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> axis_of(0, 2), pick(0, 1);
    int nonzero = 0;
    for (int n = 0; n < 20000; ++n) {
        const int axis = axis_of(rng), i = (axis + 1) % 3, j = (axis + 2) % 3;
        const double p[2][2] = {{unit(rng), unit(rng)}, {unit(rng), unit(rng)}};
        Vec3 points[4];
        for (Vec3& point : points) {
            const int which = pick(rng);
            point[axis] = unit(rng);
            point[i] = p[which][0];
            point[j] = p[which][1];
        }
        const PredicateCounters before = predicate_counters();
        ASSERT_EQ(orient3d(points[0], points[1], points[2], points[3]), 0) << "seed " << seed << " case " << n;
        ASSERT_EQ(predicate_counters().exact, before.exact) << "seed " << seed << " case " << n;
        // One coordinate moved off the plane by an ulp: the sign is the rationals'.
        Vec3 moved = points[3];
        moved[i] = std::nextafter(moved[i], 2.0);
        const int expected = reference_orient3d(points[0], points[1], points[2], moved);
        ASSERT_EQ(orient3d(points[0], points[1], points[2], moved), expected) << "seed " << seed << " case " << n;
        nonzero += expected != 0;
    }
    EXPECT_GT(nonzero, 1000);
}

TEST(Predicates, CountersSeeFallbacks) {
    const PredicateCounters before = predicate_counters();
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    orient3d(a, b, c, Vec3(0.25, 0.25, 1));  // decided by the filter
    orient3d(a, b, c, Vec3(0.25, 0.25, 0));  // coplanar, every product exact: cheap stage
    // Coplanar in a tilted plane with products that round: only the exact path decides.
    const Vec3 p(0.1, 0.2, 0.3), q(0.7, 0.11, 0.5), r(0.3, 0.9, 0.13);
    const Vec3 m = p + 0.5 * (q - p);
    EXPECT_EQ(orient3d(p, q, r, m), reference_orient3d(p, q, r, m));
    const PredicateCounters after = predicate_counters();
    EXPECT_EQ(after.filtered - before.filtered, 1u);
    EXPECT_EQ(after.shortcut - before.shortcut, 1u);
    EXPECT_EQ(after.exact - before.exact, 1u);
}

// The inline filter the traversal uses (adjacent_filter.hpp) and orient3d runs first: a
// sign it certifies is the exact sign, on grid points (exact zeros) and float32 points.
TEST(Predicates, Orient3dFilteredSignIsTheRationalSign) {
    const std::uint64_t seed = 0x03D;
    std::mt19937_64 rng(seed);
    int decided = 0;
    for (int n = 0; n < 100000; ++n) {
        std::array<Vec3, 4> p;
        const bool grid = n % 2 == 0;
        std::uniform_int_distribution<int> cell(-2, 2);
        std::uniform_real_distribution<float> real(-1, 1);
        for (Vec3& q : p)
            q = grid ? Vec3(cell(rng), cell(rng), cell(rng)) * 0.375
                     : Vec3(real(rng), real(rng), real(rng)).cast<double>();
        const int filtered = filter::orient3d_filtered(p[0], p[1], p[2], p[3]);
        if (filtered == 0) continue;
        ++decided;
        ASSERT_EQ(filtered, reference_orient3d(p[0], p[1], p[2], p[3])) << "seed " << seed << " case " << n;
    }
    std::printf("seed %#llx: %d of 100000 signs certified by the filter\n", static_cast<unsigned long long>(seed), decided);
    EXPECT_GT(decided, 40000);
}

}  // namespace
}  // namespace collidescope
