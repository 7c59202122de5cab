#pragma once
// The shapes the region tests cut with each other, whose intersections are known in closed
// form: UV spheres, a torus, a square plane; and the frame's regions through the aabb method.

#include "support/scene_builders.hpp"

#include "collidescope/pipeline.hpp"
#include "collidescope/regions.hpp"
#include "datasets/generated_source.hpp"
#include "datasets/shapes.hpp"

#include <cmath>
#include <numbers>

namespace collidescope::testing {

constexpr double k_pi = std::numbers::pi;

inline MeshData sphere(std::uint32_t segments, std::uint32_t rings, const Vec3& centre, double radius) {
    MeshData mesh;
    mesh.triangles = datasets::sphere_triangles(segments, rings);
    mesh.vertices.resize(segments * rings + 2);
    datasets::unit_sphere_vertices(segments, rings, mesh.vertices);
    for (Vec3& v : mesh.vertices) v = centre + radius * v;
    return mesh;
}

// A closed torus about the z axis (major radius R, minor r), `around` x `tube` vertices.
inline MeshData torus(std::uint32_t around, std::uint32_t tube, double R, double r, double phase = 0.37) {
    MeshData mesh;
    for (std::uint32_t j = 0; j < tube; ++j) {  // vertex (i, j) at j * around + i (torus_triangles)
        for (std::uint32_t i = 0; i < around; ++i) {
            const double u = 2 * k_pi * i / around, v = 2 * k_pi * (j + phase) / tube;
            mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                       r * std::sin(v));
        }
    }
    mesh.triangles = datasets::torus_triangles(around, tube);
    return mesh;
}

inline MeshData plane_at(double z, double half, std::uint32_t cells) {
    return surface_grid(cells, cells, [=](double u, double v) { return Vec3(-half + 2 * half * u, -half + 2 * half * v, z); });
}

/// The pairs from the aabb method (tested against brute force in tests/bvh and tests/pipeline;
/// brute force itself is too slow for the finer spheres), then find_regions.
inline std::vector<TrianglePair> pairs_of(const Frame& frame, bool self) {
    Pipeline pipeline({"aabb", self, 0});
    return pipeline.process(frame).colliding_pairs;
}

inline std::vector<Region> regions_of(const Frame& frame, bool self) { return find_regions(frame, pairs_of(frame, self)); }

}  // namespace collidescope::testing

namespace collidescope::testing {

/// A closed box from lo to hi: 8 corners, 12 triangles facing out.
inline MeshData box_mesh(const Vec3& lo, const Vec3& hi) {
    MeshData mesh;
    for (int k = 0; k < 8; ++k) mesh.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

}  // namespace collidescope::testing
