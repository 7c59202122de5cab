// Meshes the generated scenes share (shapes.hpp).

#include "datasets/shapes.hpp"

#include <cmath>
#include <numbers>

namespace collidescope::datasets {

std::vector<TriIndices> sphere_triangles(std::uint32_t segments, std::uint32_t rings) {
    std::vector<TriIndices> triangles;
    const auto at = [segments](std::uint32_t i, std::uint32_t r) { return r * segments + i % segments; };
    for (std::uint32_t r = 0; r + 1 < rings; ++r)
        for (std::uint32_t i = 0; i < segments; ++i) {
            triangles.push_back({at(i, r), at(i + 1, r), at(i + 1, r + 1)});
            triangles.push_back({at(i, r), at(i + 1, r + 1), at(i, r + 1)});
        }
    const std::uint32_t south = rings * segments, north = south + 1;
    for (std::uint32_t i = 0; i < segments; ++i) {
        triangles.push_back({south, at(i + 1, 0), at(i, 0)});
        triangles.push_back({north, at(i, rings - 1), at(i + 1, rings - 1)});
    }
    return triangles;
}

void unit_sphere_vertices(std::uint32_t segments, std::uint32_t rings, std::span<Vec3> out) {
    constexpr double pi = std::numbers::pi;
    for (std::uint32_t r = 0; r < rings; ++r) {
        const double polar = pi * (r + 1) / (rings + 1);
        for (std::uint32_t i = 0; i < segments; ++i) {
            const double azimuth = 2 * pi * i / segments;
            out[std::size_t{r} * segments + i] =
                Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), -std::cos(polar));
        }
    }
    out[std::size_t{rings} * segments] = Vec3(0, 0, -1);
    out[std::size_t{rings} * segments + 1] = Vec3(0, 0, 1);
}

std::vector<TriIndices> tube_triangles(std::uint32_t around, std::uint32_t along) {
    std::vector<TriIndices> triangles;
    triangles.reserve(std::size_t{2} * around * (along - 1));
    const auto at = [around](std::uint32_t i, std::uint32_t k) { return k * around + i % around; };
    for (std::uint32_t k = 0; k + 1 < along; ++k)
        for (std::uint32_t i = 0; i < around; ++i) {
            triangles.push_back({at(i, k), at(i + 1, k), at(i + 1, k + 1)});
            triangles.push_back({at(i, k), at(i + 1, k + 1), at(i, k + 1)});
        }
    return triangles;
}

}  // namespace collidescope::datasets
