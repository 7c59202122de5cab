// The predicates, the triangle test and the self rule against exact rationals on sets built to
// be degenerate (issue 23): repeated and shared vertices, axis-aligned and tilted coplanar
// points, grid-snapped coordinates (dyadic and not), touching contact. These are the inputs
// where the float filter cannot decide and the cheap exact stage (repeated points, exact double
// evaluation) must give the same sign as GMP. Seeds are fixed and printed on failure.

#include "collidescope/geometry.hpp"
#include "support/rational_reference.hpp"
#include "support/random_triangles.hpp"
#include "support/sweep_size.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <random>
#include <string>

namespace collidescope {
namespace {

using testing::describe;
using testing::reference_self_collide;
using testing::reference_triangles_intersect;

int rational_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    mpq_class m[3][3];
    const Vec3* rows[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) m[i][k] = mpq_class((*rows[i])[k]) - mpq_class(d[k]);
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sgn(det);
}

int rational_orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const mpq_class det = (mpq_class(a[i]) - c[i]) * (mpq_class(b[j]) - c[j]) -
                          (mpq_class(a[j]) - c[j]) * (mpq_class(b[i]) - c[i]);
    return sgn(det);
}

/// Points of a small degenerate pool, so that random picks repeat points, share planes and
/// lines. Kinds: lattice with a dyadic step, lattice with a non-dyadic step (0.1: inexact
/// products), an axis-aligned plane z = 0.3 (non-dyadic coordinates), a tilted lattice plane
/// (origin + i e1 + j e2 with short-mantissa e1, e2), and a tilted plane through rounded
/// points (nearly but not exactly coplanar: the expansion path decides).
struct PointPool {
    std::string kind;
    std::vector<Vec3> points;
};

std::vector<PointPool> degenerate_pools() {
    std::vector<PointPool> pools;
    const auto lattice = [](const std::string& kind, double step, const Vec3& origin, int n,
                            bool flat) {
        PointPool pool{kind, {}};
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < (flat ? 1 : n); ++k)
                    pool.points.push_back(origin + step * Vec3(i, j, k));
        return pool;
    };
    pools.push_back(lattice("dyadic lattice", 0.125, Vec3(-0.25, 0.5, 1.0), 4, false));
    pools.push_back(lattice("decimal lattice", 0.1, Vec3(0.3, -0.7, 0.11), 4, false));
    pools.push_back(lattice("axis-aligned plane", 0.0137, Vec3(-0.85, -0.85, 0.3), 6, true));
    PointPool tilted{"tilted lattice plane", {}};
    const Vec3 e1(0.25, 0.125, -0.375), e2(-0.125, 0.5, 0.25), o(1.5, -2.0, 0.75);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) tilted.points.push_back(o + i * e1 + j * e2);
    pools.push_back(tilted);
    PointPool rounded{"rounded tilted plane", {}};
    const Vec3 f1(0.1, 0.037, -0.29), f2(-0.061, 0.3, 0.17);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) rounded.points.push_back(Vec3(0.3, 0.2, -0.1) + i * f1 + j * f2);
    pools.push_back(rounded);
    return pools;
}

TEST(DegenerateSets, PredicatesMatchRationals) {
    const std::uint64_t seed = 0xDE6E;
    std::mt19937_64 rng(seed);
    for (const PointPool& pool : degenerate_pools()) {
        std::uniform_int_distribution<std::size_t> pick(0, pool.points.size() - 1);
        int zeros = 0, nonzeros = 0;
        const PredicateCounters before = predicate_counters();
        for (int n = 0; n < 20000; ++n) {
            const Vec3 &a = pool.points[pick(rng)], &b = pool.points[pick(rng)],
                       &c = pool.points[pick(rng)], &d = pool.points[pick(rng)];
            const int expected = rational_orient3d(a, b, c, d);
            ASSERT_EQ(orient3d(a, b, c, d), expected)
                << "seed " << seed << " pool " << pool.kind << " case " << n;
            (expected == 0 ? zeros : nonzeros)++;
            for (int drop = 0; drop < 3; ++drop) {
                const int expected2 = rational_orient2d(a, b, d, drop);
                ASSERT_EQ(orient2d(a, b, d, drop), expected2)
                    << "seed " << seed << " pool " << pool.kind << " case " << n << " drop " << drop;
                (expected2 == 0 ? zeros : nonzeros)++;
            }
        }
        const PredicateCounters after = predicate_counters();
        std::printf("pool %s: zeros %d nonzeros %d, filtered %llu, cheap exact %llu, "
                    "expansions %llu\n",
                    pool.kind.c_str(), zeros, nonzeros,
                    static_cast<unsigned long long>(after.filtered - before.filtered),
                    static_cast<unsigned long long>(after.shortcut - before.shortcut),
                    static_cast<unsigned long long>(after.exact - before.exact));
        EXPECT_GT(zeros, 1000) << pool.kind;  // both outcomes exercised (orient3d and orient2d)
        EXPECT_GT(nonzeros, 1000) << pool.kind;
        // Where a cheap exact argument exists, the expansions are not reached: dyadic
        // coordinates make every product exact; in the axis-aligned plane orient3d always has
        // a zero column, and only orient2d on collinear non-dyadic points needs expansions.
        const std::uint64_t expansions = after.exact - before.exact;
        if (pool.kind == "dyadic lattice" || pool.kind == "tilted lattice plane") {
            EXPECT_EQ(expansions, 0u) << pool.kind;
        }
        if (pool.kind == "axis-aligned plane") {
            EXPECT_LT(expansions, 800u) << pool.kind;  // < 1%
        }
        EXPECT_GT(after.shortcut - before.shortcut, 0u) << pool.kind;
    }
}

TEST(DegenerateSets, RepeatedPointsAreDecidedWithoutExpansions) {
    const Vec3 a(0.1, 0.2, 0.3), b(1.7, -0.3, 2.9), c(-0.6, 0.45, 0.01);
    const PredicateCounters before = predicate_counters();
    EXPECT_EQ(orient3d(a, b, c, a), 0);
    EXPECT_EQ(orient3d(a, a, c, b), 0);
    EXPECT_EQ(orient2d(a, b, b, 2), 0);
    EXPECT_EQ(orient2d(a, Vec3(0.1, 0.2, 9.0), c, 2), 0);  // equal after dropping z
    const PredicateCounters after = predicate_counters();
    EXPECT_EQ(after.exact - before.exact, 0u);
    EXPECT_EQ(after.shortcut - before.shortcut, 4u);
}

/// Triangle pairs over a degenerate pool (shared corners by position, coplanar, touching,
/// collinear corners): the triangle test against the rational LP reference.
TEST(DegenerateSets, TriangleTestMatchesRationalReference) {
    const std::uint64_t seed = 0x7A1A;
    std::mt19937_64 rng(seed);
    for (const PointPool& pool : degenerate_pools()) {
        std::uniform_int_distribution<std::size_t> pick(0, pool.points.size() - 1);
        int hits = 0;
        const int count = testing::sweep_size(3000);
        for (int n = 0; n < count; ++n) {
            std::array<Vec3, 3> a, b;
            for (Vec3& p : a) p = pool.points[pick(rng)];
            for (Vec3& p : b) p = pool.points[pick(rng)];
            const bool expected = reference_triangles_intersect(a, b);
            ASSERT_EQ(triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]), expected)
                << "seed " << seed << " pool " << pool.kind << " case " << n << ": " << describe(a, b);
            hits += expected;
        }
        std::printf("pool %s: %d pairs, hit rate %.3f\n", pool.kind.c_str(), count,
                    double(hits) / count);
        EXPECT_GT(hits, count / 20) << pool.kind;
        EXPECT_LT(hits, count - count / 20) << pool.kind;
    }
}

/// Adjacent pairs of one object over the degenerate pools: indices shared by construction
/// (one or two), positions drawn from the pool (so some unshared corners coincide too).
TEST(DegenerateSets, SelfRuleMatchesRationalReference) {
    const std::uint64_t seed = 0x5E1FDE6E;
    std::mt19937_64 rng(seed);
    for (const PointPool& pool : degenerate_pools()) {
        std::uniform_int_distribution<std::size_t> pick(0, pool.points.size() - 1);
        std::uniform_int_distribution<int> coin(0, 1);
        int hits = 0;
        const int count = testing::sweep_size(3000);
        for (int n = 0; n < count; ++n) {
            // Indices 0, 1 shared (or only 0), 2 and 3 private; positions by index.
            const bool share_edge = coin(rng) == 1;
            std::array<Vec3, 4> at;
            for (Vec3& p : at) p = pool.points[pick(rng)];
            const TriIndices ia{0, 1, 2};
            const TriIndices ib = share_edge ? TriIndices{1, 0, 3} : TriIndices{0, 3, 4};
            const std::array<Vec3, 3> pa{at[0], at[1], at[2]};
            const Vec3 extra = pool.points[pick(rng)];
            const std::array<Vec3, 3> pb =
                share_edge ? std::array<Vec3, 3>{at[1], at[0], at[3]}
                           : std::array<Vec3, 3>{at[0], at[3], extra};
            const bool expected = reference_self_collide(ia, pa, ib, pb);
            ASSERT_EQ(self_triangles_collide(ia, pa, ib, pb), expected)
                << "seed " << seed << " pool " << pool.kind << " case " << n << ": " << describe(pa, pb);
            hits += expected;
        }
        std::printf("pool %s: %d adjacent pairs, collide rate %.3f\n", pool.kind.c_str(), count,
                    double(hits) / count);
        EXPECT_GT(hits, count / 50) << pool.kind;
        EXPECT_LT(hits, count - count / 50) << pool.kind;
    }
}

/// Coplanar pairs sharing one vertex (the flat-cloth case the self rule's coplanar shortcut
/// decides from the cones at v), on the two exactly planar pools, both argument orders.
TEST(DegenerateSets, CoplanarSharedVertexPairsMatchRationalReference) {
    const std::uint64_t seed = 0xC0C0;
    std::mt19937_64 rng(seed);
    for (const PointPool& pool : degenerate_pools()) {
        if (pool.kind != "axis-aligned plane" && pool.kind != "tilted lattice plane") continue;
        std::uniform_int_distribution<std::size_t> pick(0, pool.points.size() - 1);
        int hits = 0;
        const int count = 4000;
        for (int n = 0; n < count; ++n) {
            const Vec3 v = pool.points[pick(rng)];
            const std::array<Vec3, 3> pa{v, pool.points[pick(rng)], pool.points[pick(rng)]};
            const std::array<Vec3, 3> pb{v, pool.points[pick(rng)], pool.points[pick(rng)]};
            const TriIndices ia{0, 1, 2}, ib{0, 3, 4};
            const bool expected = reference_self_collide(ia, pa, ib, pb);
            ASSERT_EQ(self_triangles_collide(ia, pa, ib, pb), expected)
                << "seed " << seed << " pool " << pool.kind << " case " << n << ": " << describe(pa, pb);
            ASSERT_EQ(self_triangles_collide(ib, pb, ia, pa), expected)
                << "seed " << seed << " pool " << pool.kind << " case " << n << " (swapped)";
            hits += expected;
        }
        std::printf("pool %s: %d coplanar shared-vertex pairs, collide rate %.3f\n", pool.kind.c_str(),
                    count, double(hits) / count);
        EXPECT_GT(hits, count / 10) << pool.kind;
        EXPECT_LT(hits, count - count / 10) << pool.kind;
    }
}

}  // namespace
}  // namespace collidescope
