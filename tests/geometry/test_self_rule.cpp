// self_triangles_collide: the self-collision rule of DESIGN.md against constructed cases and
// the rational reference (maximising over the intersection, tests/support).

#include "collidescope/geometry.hpp"
#include "support/random_triangles.hpp"
#include "support/rational_reference.hpp"
#include "support/sweep_size.hpp"

#include <gtest/gtest.h>

#include <random>

namespace collidescope {
namespace {

using testing::describe;
using testing::reference_self_collide;
using Tri = std::array<Vec3, 3>;

struct SelfCase {
    const char* name;
    TriIndices ia;
    TriIndices ib;
    std::vector<Vec3> vertices;
    bool expected;
};

Tri corners(const TriIndices& t, const std::vector<Vec3>& v) { return {v[t[0]], v[t[1]], v[t[2]]}; }

TEST(SelfRule, ConstructedCases) {
    const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
    const std::vector<SelfCase> cases = {
        {"shared vertex only", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(-1, 0, 0), Vec3(0, -1, 0)}, false},
        {"shared vertex, edge pierces", {0, 1, 2}, {0, 3, 4},
         {o, x, y, Vec3(0.25, 0.25, 1), Vec3(0.25, 0.25, -1)}, true},
        {"shared vertex, coplanar overlap", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(1, 1, 0), Vec3(-1, 1, 0)}, true},
        {"shared vertex, edges overlap", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(2, 0, 0), Vec3(0, 0, 1)}, true},
        {"shared vertex, touching edge to edge elsewhere", {0, 1, 2}, {0, 3, 4},
         {o, x, y, Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, -1)}, true},
        {"shared vertex, perpendicular", {0, 1, 2}, {0, 3, 4}, {o, x, y, Vec3(0, 0, 1), Vec3(-1, -1, 1)}, false},
        {"shared edge, flat neighbour", {0, 1, 2}, {1, 0, 3}, {o, x, y, Vec3(0, -1, 0)}, false},
        {"shared edge, bent neighbour", {0, 1, 2}, {1, 0, 3}, {o, x, y, Vec3(0, 0, 1)}, false},
        {"shared edge, fold-over", {0, 1, 2}, {1, 0, 3}, {o, x, y, Vec3(0.5, 2, 0)}, true},
        {"identical index sets", {0, 1, 2}, {2, 0, 1}, {o, x, y}, false},
        {"shared edge, both segments past one end", {0, 1, 2}, {0, 1, 3},
         {o, x, Vec3(2, 0, 0), Vec3(3, 0, 0)}, true},
        {"shared edge, segments past opposite ends", {0, 1, 2}, {0, 1, 3},
         {o, x, Vec3(2, 0, 0), Vec3(-1, 0, 0)}, false},
        {"shared edge of coincident ends", {0, 1, 2}, {0, 1, 3}, {o, o, x, Vec3(2, 0, 0)}, true},
        {"repeated index, segment along edge", {0, 1, 1}, {0, 2, 3}, {o, Vec3(0.5, 0, 0), x, y}, true},
        {"no shared index, coincident positions", {0, 1, 2}, {3, 4, 5},
         {o, x, y, o, Vec3(-1, 0, 0), Vec3(0, -1, 0)}, true},
    };
    for (const SelfCase& c : cases) {
        const Tri pa = corners(c.ia, c.vertices), pb = corners(c.ib, c.vertices);
        EXPECT_EQ(self_triangles_collide(c.ia, pa, c.ib, pb), c.expected) << c.name;
        EXPECT_EQ(self_triangles_collide(c.ib, pb, c.ia, pa), c.expected) << c.name << " (swapped)";
        EXPECT_EQ(reference_self_collide(c.ia, pa, c.ib, pb), c.expected) << c.name << " (reference)";
    }
}

TEST(SelfRule, MatchesRationalReferenceOnRandomAdjacentPairs) {
    const std::uint64_t seed = 0x5E1F;
    const int count = testing::sweep_size(20000);
    std::mt19937_64 rng(seed);
    int hits = 0;
    for (int n = 0; n < count; ++n) {
        const testing::SelfPairCase c = testing::random_self_pair(rng);
        const bool expected = reference_self_collide(c.ia, c.pa, c.ib, c.pb);
        ASSERT_EQ(self_triangles_collide(c.ia, c.pa, c.ib, c.pb), expected)
            << "seed " << seed << " case " << n << " indices " << c.ia[0] << c.ia[1] << c.ia[2] << "/"
            << c.ib[0] << c.ib[1] << c.ib[2] << ": " << describe(c.pa, c.pb);
        hits += expected;
    }
    std::printf("seed %#llx: %d adjacent pairs, collide rate %.3f\n",
                static_cast<unsigned long long>(seed), count, double(hits) / count);
    EXPECT_GT(hits, count / 10);
    EXPECT_LT(hits, count - count / 10);
}

}  // namespace
}  // namespace collidescope
