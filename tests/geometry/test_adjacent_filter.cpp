// adjacent_apart (geometry/adjacent_filter.hpp), the traversal's decision on pairs that share
// a vertex index: it may only say "apart" where the exact self rule and the rational
// reference say the pair does not collide (the filtered orient3d sign it uses is checked
// against rationals in test_predicates.cpp).

#include "collidescope/geometry.hpp"
#include "geometry/adjacent_filter.hpp"
#include "support/random_triangles.hpp"
#include "support/rational_reference.hpp"
#include "support/sweep_size.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

namespace collidescope {
namespace {

using filter::adjacent_apart;
using testing::describe;
using testing::reference_self_collide;

struct AdjacentCase {
    const char* name;
    TriIndices ia;
    TriIndices ib;
    std::vector<Vec3> vertices;
    bool apart;  // what adjacent_apart must answer
};

TEST(AdjacentFilter, ConstructedCases) {
    const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
    const std::vector<AdjacentCase> cases = {
        {"shared edge, bent neighbour", {0, 1, 2}, {1, 0, 3}, {o, x, y, Vec3(0, -1, 1)}, true},
        {"shared edge, flat neighbour (exact zero: left to the rule)", {0, 1, 2}, {1, 0, 3},
         {o, x, y, Vec3(0, -1, 0)}, false},
        {"shared edge, fold-over", {0, 1, 2}, {1, 0, 3}, {o, x, y, Vec3(0.5, 2, 0)}, false},
        {"shared vertex, perpendicular", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(0, 0, 1), Vec3(-1, -1, 1)}, true},
        {"shared vertex, edge pierces", {0, 1, 2}, {0, 3, 4},
         {o, x, y, Vec3(0.25, 0.25, 1), Vec3(0.25, 0.25, -1)}, false},
        {"shared vertex, coplanar fan", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(-1, 0, 0), Vec3(0, -1, 0)}, false},
        {"no shared index", {0, 1, 2}, {3, 4, 5},
         {o, x, y, Vec3(5, 5, 5), Vec3(6, 5, 5), Vec3(5, 6, 7)}, false},
        {"repeated index", {0, 1, 1}, {0, 2, 3}, {o, x, y, Vec3(0, 0, 1)}, false},
        {"identical index sets", {0, 1, 2}, {2, 0, 1}, {o, x, y}, false},
    };
    for (const AdjacentCase& c : cases) {
        EXPECT_EQ(adjacent_apart(c.ia, c.ib, c.vertices.data()), c.apart) << c.name;
        EXPECT_EQ(adjacent_apart(c.ib, c.ia, c.vertices.data()), c.apart) << c.name << " (swapped)";
        if (c.apart) {
            const std::array<Vec3, 3> pa = {c.vertices[c.ia[0]], c.vertices[c.ia[1]], c.vertices[c.ia[2]]};
            const std::array<Vec3, 3> pb = {c.vertices[c.ib[0]], c.vertices[c.ib[1]], c.vertices[c.ib[2]]};
            EXPECT_FALSE(self_triangles_collide(c.ia, pa, c.ib, pb)) << c.name;
        }
    }
}

// Random pairs sharing one or two indices over a pool of six points: grid points (coplanar,
// collinear, coincident: the degenerate sets) or float32 points in general position.
TEST(AdjacentFilter, ApartOnlyWhereTheRuleSaysApart) {
    const std::uint64_t seed = 0xAD1A;
    const int count = testing::sweep_size(40000);
    std::mt19937_64 rng(seed);
    int apart = 0, colliding = 0;
    for (int n = 0; n < count; ++n) {
        const testing::SelfPairCase c = testing::random_self_pair(rng);
        std::vector<Vec3> vertices(6, Vec3::Zero());
        for (int k = 0; k < 3; ++k) {
            vertices[c.ia[k]] = c.pa[k];
            vertices[c.ib[k]] = c.pb[k];
        }
        const bool ours = adjacent_apart(c.ia, c.ib, vertices.data());
        ASSERT_EQ(ours, adjacent_apart(c.ib, c.ia, vertices.data())) << "seed " << seed << " case " << n;
        const bool collide = self_triangles_collide(c.ia, c.pa, c.ib, c.pb);
        ASSERT_EQ(collide, reference_self_collide(c.ia, c.pa, c.ib, c.pb)) << "seed " << seed << " case " << n;
        ASSERT_FALSE(ours && collide)
            << "seed " << seed << " case " << n << " indices " << c.ia[0] << c.ia[1] << c.ia[2] << "/" << c.ib[0]
            << c.ib[1] << c.ib[2] << ": " << describe(c.pa, c.pb);
        apart += ours;
        colliding += collide;
    }
    std::printf("seed %#llx: %d adjacent pairs, %d proven apart by the filter, %d colliding\n",
                static_cast<unsigned long long>(seed), count, apart, colliding);
    // It must decide a real share of the non-colliding pairs, or it does nothing.
    EXPECT_GT(apart, (count - colliding) / 4);
}

}  // namespace
}  // namespace collidescope
