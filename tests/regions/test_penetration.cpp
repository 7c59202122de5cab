// Inside areas and penetration depth against answers known in closed form (a sheet through a
// box, a sphere pushed into a box by a known depth, at random rotations) and against a slow,
// obvious reference (winding numbers and brute-force distances) on random overlapping spheres;
// undefined where no object is closed.

#include "support/scene_builders.hpp"

#include "collidescope/regions.hpp"
#include "regions/region_shapes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <random>

namespace collidescope {
namespace {

using namespace testing;

MeshData transformed(MeshData mesh, const Eigen::Quaterniond& rotation, const Vec3& offset = Vec3::Zero()) {
    for (Vec3& v : mesh.vertices) v = rotation * v + offset;
    return mesh;
}

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

// The winding number of a closed mesh around p (solid angles, Van Oosterom and Strackee).
double winding_number(const MeshData& mesh, const Vec3& p) {
    double sum = 0;
    for (const TriIndices& t : mesh.triangles) {
        const Vec3 a = mesh.vertices[t[0]] - p, b = mesh.vertices[t[1]] - p, c = mesh.vertices[t[2]] - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        sum += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
    }
    return sum / (4 * k_pi);
}

double brute_distance(const MeshData& mesh, const Vec3& p) {
    double best = INFINITY;
    for (const TriIndices& t : mesh.triangles) {
        // Sampled finely enough for a reference? No: the exact closest point, through Eigen's
        // projection onto the plane and the three edges, written out independently.
        const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
        const Vec3 n = (b - a).cross(c - a).normalized();
        const Vec3 q = p - n.dot(p - a) * n;
        const auto side = [&](const Vec3& u, const Vec3& v) { return n.dot((v - u).cross(q - u)) >= 0; };
        if (side(a, b) && side(b, c) && side(c, a)) {
            best = std::min(best, (p - q).norm());
            continue;
        }
        for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
            const double s = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
            best = std::min(best, (p - (u + s * (v - u))).norm());
        }
    }
    return best;
}

TEST(Penetration, ASheetThroughABoxHasTheBoxsSectionInsideAndItsDeepestVertexAsDepth) {
    for (const std::uint64_t seed : {0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u}) {
        std::mt19937_64 rng(seed);
        const Eigen::Quaterniond rotation = seed < 2 ? Eigen::Quaterniond::Identity() : random_rotation(rng);
        std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
        // Sheet vertices at -2 + 4k/7; the inside ones nearest the centre are 0.7 below the top
        // face. Seed 1: at -2 + k, so the box's sides run along the sheet's edges and through
        // its vertices (those on the box are not inside; the centre one is, 0.7 deep).
        const Frame frame = make_frame({transformed(plane_at(0.3, 2.0, seed == 1 ? 4 : 7), rotation),
                                        transformed(box_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1)), rotation)});
        const std::vector<Region> regions = regions_of(frame, false);
        ASSERT_EQ(regions.size(), 1u);
        EXPECT_NEAR(regions[0].inside_area_a, 4.0, 1e-12);
        EXPECT_TRUE(std::isnan(regions[0].inside_area_b));  // the sheet has no inside
        EXPECT_NEAR(regions[0].depth, 0.7, 1e-12);
    }
}

TEST(Penetration, ASpherePushedIntoABoxByAKnownDepthHasThatDepth) {
    const double radius = 0.5;
    for (const double pushed : {0.01, 0.2, 0.45}) {
        for (const std::uint64_t seed : {0u, 5u}) {
            std::mt19937_64 rng(seed);
            const Eigen::Quaterniond rotation = seed == 0 ? Eigen::Quaterniond::Identity() : random_rotation(rng);
            std::printf("pushed %.2f seed %llu\n", pushed, static_cast<unsigned long long>(seed));
            // The sphere's south pole is a vertex, `pushed` below the box's top face.
            const MeshData ball = sphere(48, 24, Vec3(0.1, -0.2, 1 - pushed + radius), radius);
            const Frame frame = make_frame({transformed(box_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1)), rotation),
                                            transformed(ball, rotation)});
            const std::vector<Region> regions = regions_of(frame, false);
            ASSERT_EQ(regions.size(), 1u);
            EXPECT_NEAR(regions[0].depth, pushed, 1e-12);
            // The top face inside the ball: about the disk the sphere cuts; the ball inside
            // the box: about the spherical cap (both polygonal, so a few per cent smaller).
            const double disk = k_pi * (2 * radius * pushed - pushed * pushed), cap = 2 * k_pi * radius * pushed;
            // At 0.01 the cut lies between the first two rings: 10% smaller there.
            const double tolerance = pushed < 0.1 ? 0.15 : 0.03;
            EXPECT_NEAR(regions[0].inside_area_a, disk, tolerance * disk);
            EXPECT_NEAR(regions[0].inside_area_b, cap, tolerance * cap);
        }
    }
}

// The reference: each triangle of X cut into m x m small ones, counted inside Y by the winding
// number at their centres; the depth from every vertex of X inside Y (one region here).
struct Reference {
    double area = 0;
    double depth = 0;
};
Reference reference(const MeshData& x, const MeshData& y, int m) {
    Reference r;
    for (const Vec3& v : x.vertices) {
        if (winding_number(y, v) > 0.5) r.depth = std::max(r.depth, brute_distance(y, v));
    }
    for (const TriIndices& t : x.triangles) {
        const Vec3 a = x.vertices[t[0]], b = x.vertices[t[1]], c = x.vertices[t[2]];
        const double small = 0.5 * (b - a).cross(c - a).norm() / (m * m);
        for (int i = 0; i < m; ++i) {
            for (int j = 0; i + j < m; ++j) {
                const auto at = [&](double u, double v) { return a + (u / m) * (b - a) + (v / m) * (c - a); };
                if (winding_number(y, at(i + 1.0 / 3, j + 1.0 / 3)) > 0.5) r.area += small;
                if (i + j + 1 < m && winding_number(y, at(i + 2.0 / 3, j + 2.0 / 3)) > 0.5) r.area += small;
            }
        }
    }
    return r;
}

TEST(Penetration, RandomOverlappingSpheresAgreeWithWindingNumbersAndBruteForceDistances) {
    for (const std::uint64_t seed : {11u, 12u, 13u}) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(-1, 1);
        const Vec3 offset = Vec3(1.0 + 0.3 * unit(rng), 0.2 * unit(rng), 0.2 * unit(rng));
        MeshData a = sphere(14, 7, Vec3::Zero(), 1.0), b = sphere(11, 9, offset, 0.8 + 0.2 * unit(rng));
        for (Vec3& v : a.vertices) v *= 1 + 0.05 * unit(rng);  // bumpy, so no symmetry helps
        for (Vec3& v : b.vertices) v += 0.03 * Vec3(unit(rng), unit(rng), unit(rng));
        const Frame frame = make_frame({a, b});
        const std::vector<Region> regions = regions_of(frame, false);
        ASSERT_EQ(regions.size(), 1u) << seed;
        const Reference in_b = reference(a, b, 24), in_a = reference(b, a, 24);
        std::printf("seed %llu: area a %.5f (reference %.5f), b %.5f (%.5f), depth %.6f (%.6f)\n",
                    static_cast<unsigned long long>(seed), regions[0].inside_area_a, in_b.area, regions[0].inside_area_b,
                    in_a.area, regions[0].depth, std::max(in_a.depth, in_b.depth));
        EXPECT_NEAR(regions[0].inside_area_a, in_b.area, 0.02 * in_b.area);
        EXPECT_NEAR(regions[0].inside_area_b, in_a.area, 0.02 * in_a.area);
        EXPECT_NEAR(regions[0].depth, std::max(in_a.depth, in_b.depth), 1e-12);
    }
}

TEST(Penetration, IsUndefinedForSelfContactAndOpenSurfaces) {
    const Frame sheets = make_frame({plane_at(0.0, 1.0, 6), transformed(plane_at(0.0, 1.0, 5), Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Vec3::UnitX())))});
    for (const Region& region : regions_of(sheets, false)) {
        EXPECT_TRUE(std::isnan(region.depth));
        EXPECT_TRUE(std::isnan(region.inside_area_a));
        EXPECT_TRUE(std::isnan(region.inside_area_b));
    }
    // A box with one triangle twice is not closed: no inside, no depth, but still its region.
    MeshData broken = box_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1));
    broken.triangles.push_back(broken.triangles[2]);
    const std::vector<Region> regions = regions_of(make_frame({plane_at(0.3, 2.0, 7), broken}), false);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_TRUE(std::isnan(regions[0].depth));
    EXPECT_TRUE(std::isnan(regions[0].inside_area_a));
}

}  // namespace
}  // namespace collidescope
