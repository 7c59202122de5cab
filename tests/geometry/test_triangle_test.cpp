// triangles_intersect against constructed cases with known answers, and against the
// rational LP reference (tests/support) on 100,000 seeded near-contact pairs (the first
// 25,000 in a sanitizer build, support/sweep_size.hpp).

#include "collidescope/geometry.hpp"
#include "support/random_triangles.hpp"
#include "support/rational_reference.hpp"
#include "support/sweep_size.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace collidescope {
namespace {

using testing::describe;
using testing::reference_triangles_intersect;
using Tri = std::array<Vec3, 3>;

struct Constructed {
    const char* name;
    Tri a;
    Tri b;
    bool expected;
};

constexpr double kTiny = 0x1p-50;

const std::vector<Constructed>& constructed_cases() {
    const Tri base = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
    static const std::vector<Constructed> cases = {
        {"coplanar overlap", base, {Vec3(0.5, 0.5, 0), Vec3(3, 0.5, 0), Vec3(0.5, 3, 0)}, true},
        {"coplanar containment", base, {Vec3(0.2, 0.2, 0), Vec3(0.4, 0.2, 0), Vec3(0.2, 0.4, 0)}, true},
        {"coplanar disjoint", base, {Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(5, 1, 0)}, false},
        {"coplanar shared edge", base, {Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(2, 2, 0)}, true},
        {"coplanar touching at a point", base, {Vec3(1, 1, 0), Vec3(2, 2, 0), Vec3(2, 1.5, 0)}, true},
        {"coplanar near miss", base,
         {Vec3(2, kTiny, 0), Vec3(kTiny, 2, 0), Vec3(2, 2, 0)}, false},
        {"edge-edge crossing", {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0)},
         {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(0, 1, 0)}, true},
        {"edge-edge near miss", {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0)},
         {Vec3(0, kTiny, -1), Vec3(0, kTiny, 1), Vec3(0, 1, 0)}, false},
        {"vertex on face", base, {Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 1), Vec3(1, 0.5, 1)}, true},
        {"vertex above face", base, {Vec3(0.5, 0.5, kTiny), Vec3(0.5, 0.5, 1), Vec3(1, 0.5, 1)}, false},
        {"vertex on edge", base, {Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(1, 1, 1)}, true},
        {"vertex beside edge", base, {Vec3(1, -kTiny, 0), Vec3(1, 0, 1), Vec3(1, 1, 1)}, false},
        {"vertex on vertex", base, {Vec3(0, 0, 0), Vec3(-1, 0, 1), Vec3(0, -1, 1)}, true},
        {"piercing", base, {Vec3(0.5, 0.5, -1), Vec3(0.6, 0.5, 1), Vec3(0.5, 0.6, 1)}, true},
        {"parallel planes", base, {Vec3(0, 0, kTiny), Vec3(2, 0, kTiny), Vec3(0, 2, kTiny)}, false},
        {"segment through face", {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)},
         {Vec3(3, 0, 0), Vec3(0, 3, 0), Vec3(0, 0, 3)}, true},
        {"segment short of face", {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)},
         {Vec3(7, 0, 0), Vec3(0, 7, 0), Vec3(0, 0, 7)}, false},
        {"segment end on face", {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)},
         {Vec3(6, 0, 0), Vec3(0, 6, 0), Vec3(0, 0, 6)}, true},
        {"segment-segment crossing", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0)},
         {Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(1, 1, 0)}, true},
        {"segment-segment skew", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0)},
         {Vec3(1, -1, 1), Vec3(1, 1, 1), Vec3(1, 0, 1)}, false},
        {"collinear overlap", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)},
         {Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(3, 0, 0)}, true},
        {"collinear touching ends", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)},
         {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 0, 0)}, true},
        {"collinear gap", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)},
         {Vec3(std::nextafter(2.0, 3.0), 0, 0), Vec3(3, 0, 0), Vec3(3, 0, 0)}, false},
        {"point on edge", {Vec3(1, 1, 0), Vec3(1, 1, 0), Vec3(1, 1, 0)}, base, true},
        {"point above edge", {Vec3(1, 1, 0x1p-70), Vec3(1, 1, 0x1p-70), Vec3(1, 1, 0x1p-70)}, base, false},
        {"point on point", {Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)},
         {Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)}, true},
        {"point off point", {Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)},
         {Vec3(2, 0, kTiny), Vec3(2, 0, kTiny), Vec3(2, 0, kTiny)}, false},
    };
    return cases;
}

Tri scaled(const Tri& t, double s) { return {t[0] * s, t[1] * s, t[2] * s}; }

bool engine(const Tri& a, const Tri& b) { return triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]); }

TEST(TriangleTest, ConstructedCases) {
    for (const Constructed& c : constructed_cases()) {
        EXPECT_EQ(engine(c.a, c.b), c.expected) << c.name;
        EXPECT_EQ(engine(c.b, c.a), c.expected) << c.name << " (swapped)";
        EXPECT_EQ(reference_triangles_intersect(c.a, c.b), c.expected) << c.name << " (reference)";
    }
}

TEST(TriangleTest, ConstructedCasesNear1e30And1eMinus30) {
    // Power-of-two scaling is exact and keeps every answer; 1e±30 scaling is inexact, so
    // the reference decides.
    for (const Constructed& c : constructed_cases())
        for (double s : {0x1p-100, 0x1p100, 0x1p-1000, 0x1p1000}) {
            EXPECT_EQ(engine(scaled(c.a, s), scaled(c.b, s)), c.expected) << c.name << " * " << s;
        }
    for (const Constructed& c : constructed_cases())
        for (double s : {1e-30, 1e30}) {
            const Tri a = scaled(c.a, s), b = scaled(c.b, s);
            EXPECT_EQ(engine(a, b), reference_triangles_intersect(a, b)) << c.name << " * " << s;
        }
}

TEST(TriangleTest, MatchesRationalReferenceOnNearContactPairs) {
    const std::uint64_t seed = 0xC011D35C0;
    const int count = testing::sweep_size(100000);
    std::mt19937_64 rng(seed);
    std::map<std::string, std::pair<int, int>> per_kind;  // kind -> (hits, total)
    int hits = 0;
    for (int n = 0; n < count; ++n) {
        const testing::TrianglePairCase c = testing::random_near_contact_pair(rng);
        const bool expected = reference_triangles_intersect(c.a, c.b);
        ASSERT_EQ(engine(c.a, c.b), expected)
            << "seed " << seed << " case " << n << " kind " << c.kind << ": " << describe(c.a, c.b);
        hits += expected;
        const std::string base = c.kind.substr(0, c.kind.find('*'));
        per_kind[base].first += expected;
        per_kind[base].second += 1;
    }
    const double rate = double(hits) / count;
    std::printf("seed %#llx: %d pairs, hit rate %.3f\n", static_cast<unsigned long long>(seed), count, rate);
    for (const auto& [kind, ht] : per_kind) {
        std::printf("  %-12s %6d pairs, hit rate %.3f\n", kind.c_str(), ht.second, double(ht.first) / ht.second);
        EXPECT_GT(ht.first, ht.second / 20) << kind << " rarely collides: the test is too easy";
        EXPECT_LT(ht.first, ht.second - ht.second / 20) << kind << " nearly always collides";
    }
    EXPECT_GT(rate, 0.25);
    EXPECT_LT(rate, 0.75);
}

// coplanar_triangles_intersect, the entry for triangles known to share a plane, gives the
// rational reference's answer (and triangles_intersect's, which takes it for such pairs) on
// random pairs in four exact planes (z = 0.375, x = -1.25, y = -0.625 and the tilted
// x + 2y + 4z = 1.5: each projection axis is taken), corners on a coarse grid so that touching
// corners, edges along one another, corners inside the other triangle and flat triangles (of
// either) are common.
TEST(TriangleTest, CoplanarEntryAgreesWithTheRationalReference) {
    const std::uint64_t seed = 0xC0F1A7;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> grid(-8, 8);
    int hits = 0, count = testing::sweep_size(15000);
    for (int n = 0; n < count; ++n) {
        const int plane = n % 4;
        const auto corner = [&]() -> Vec3 {
            const double s = grid(rng) / 8.0, r = grid(rng) / 8.0;
            if (plane == 0) return {s, r, 0.375};
            if (plane == 1) return {-1.25, s, r};
            if (plane == 2) return {s, -0.625, r};
            return {s, r, (1.5 - s - 2 * r) / 4};
        };
        Tri a{corner(), corner(), corner()}, b{corner(), corner(), corner()};
        if (n % 10 == 7) a[2] = a[0] + 0.5 * (a[1] - a[0]);  // flat: a corner on the opposite edge's midpoint
        if (n % 10 == 3) b[2] = b[0] + 0.5 * (b[1] - b[0]);
        const bool expected = reference_triangles_intersect(a, b);
        ASSERT_EQ(coplanar_triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]), expected)
            << "seed " << seed << " case " << n << ": " << describe(a, b);
        ASSERT_EQ(triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]), expected)
            << "seed " << seed << " case " << n << ": " << describe(a, b);
        hits += expected;
    }
    std::printf("seed %#llx: %d coplanar pairs, hit rate %.3f\n", static_cast<unsigned long long>(seed), count,
                double(hits) / count);
    EXPECT_GT(hits, count / 5);
    EXPECT_LT(hits, count - count / 5);
}

}  // namespace
}  // namespace collidescope
