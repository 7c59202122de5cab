// The penetration measure's two helpers against slow, obvious answers: the nearest-triangle
// search (also after the cached tree is refit to moved vertices, and with a bound that ends it
// early) against every triangle; closedness against meshes whose answer is known.

#include "support/scene_builders.hpp"

#include "regions/mesh_shape.hpp"
#include "regions/region_shapes.hpp"
#include "regions/surface_distance.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace collidescope {
namespace {

using namespace testing;

std::shared_ptr<Topology> topology_of(const MeshData& mesh) {
    auto topology = std::make_shared<Topology>();
    topology->triangles = mesh.triangles;
    topology->vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
    topology->revision = next_topology_revision();
    return topology;
}

double slow_distance(const MeshData& mesh, const Vec3& p) {
    double best = INFINITY;
    for (const TriIndices& t : mesh.triangles) {
        const Vec3 q = regions::closest_point_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        best = std::min(best, (q - p).norm());
    }
    return best;
}

TEST(SurfaceDistance, EqualsTheNearestOfEveryTriangleBeforeAndAfterARefit) {
    const std::uint64_t seed = 7;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    MeshData mesh = sphere(24, 12, Vec3::Zero(), 1.0);
    const auto topology = topology_of(mesh);
    for (int round = 0; round < 3; ++round) {  // round 0 builds the tree, later ones refit it
        for (Vec3& v : mesh.vertices) v += 0.1 * Vec3(unit(rng), unit(rng), unit(rng));
        const regions::SurfaceDistance distance(*topology, mesh.vertices);
        for (int k = 0; k < 200; ++k) {
            const Vec3 p(1.5 * unit(rng), 1.5 * unit(rng), 1.5 * unit(rng));
            const double expected = slow_distance(mesh, p);
            EXPECT_EQ(distance(p), expected) << "round " << round << " point " << k;
            // With a bound: the distance when beyond it, else at most the bound.
            const double bound = 0.2 * (1 + unit(rng));
            const double got = distance.beyond(p, bound);
            if (expected > bound) {
                EXPECT_EQ(got, expected);
            } else {
                EXPECT_LE(got, bound);
            }
            // Started from a known distance, to some triangle: the same answers, and the
            // known triangle when none is nearer.
            const std::uint32_t some = static_cast<std::uint32_t>(rng() % mesh.triangles.size());
            const TriIndices& t = mesh.triangles[some];
            const double known =
                (regions::closest_point_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) - p).norm();
            std::uint32_t face = some;
            const double from_known = distance.beyond(p, bound, &face, known);
            EXPECT_GE(from_known, expected);
            EXPECT_LE(from_known, known);
            if (expected > bound) {
                EXPECT_EQ(from_known, expected) << "round " << round << " point " << k;
                const TriIndices& f = mesh.triangles[face];
                EXPECT_EQ((regions::closest_point_on_triangle(p, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]) - p).norm(),
                          expected);
            } else {
                EXPECT_LE(from_known, std::max(bound, 0.0));
            }
        }
    }
}

TEST(MeshShape, ClosedOnlyWithEveryEdgeOnceEachWay) {
    EXPECT_TRUE(regions::mesh_shape(*topology_of(box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1))))->closed);
    EXPECT_TRUE(regions::mesh_shape(*topology_of(sphere(8, 5, Vec3::Zero(), 1.0)))->closed);
    EXPECT_TRUE(regions::mesh_shape(*topology_of(torus(12, 6, 2.0, 0.5)))->closed);
    EXPECT_FALSE(regions::mesh_shape(*topology_of(plane_at(0, 1, 4)))->closed);  // a border
    MeshData flipped = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);  // one face turned over
    EXPECT_FALSE(regions::mesh_shape(*topology_of(flipped))->closed);
    MeshData doubled = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    doubled.triangles.push_back(doubled.triangles[0]);  // a triangle twice: edges used three times
    EXPECT_FALSE(regions::mesh_shape(*topology_of(doubled))->closed);
    MeshData repeated = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    repeated.triangles[0][1] = repeated.triangles[0][0];  // a repeated vertex
    EXPECT_FALSE(regions::mesh_shape(*topology_of(repeated))->closed);
}

}  // namespace
}  // namespace collidescope
