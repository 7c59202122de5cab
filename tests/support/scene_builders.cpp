// Test meshes and scenes.

#include "support/scene_builders.hpp"

#include <cmath>

namespace collidescope::testing {
namespace {

int uniform_int(std::mt19937_64& rng, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// Triangles of a (cells x cells) grid whose vertex (i, j) is i * (cells + 1) + j.
std::vector<TriIndices> grid_triangles(std::uint32_t cells) {
    std::vector<TriIndices> triangles;
    const std::uint32_t side = cells + 1;
    for (std::uint32_t i = 0; i < cells; ++i) {
        for (std::uint32_t j = 0; j < cells; ++j) {
            const std::uint32_t v00 = i * side + j, v01 = v00 + 1;
            const std::uint32_t v10 = v00 + side, v11 = v10 + 1;
            triangles.push_back({v00, v10, v11});
            triangles.push_back({v00, v11, v01});
        }
    }
    return triangles;
}

}  // namespace

MeshData grid_sheet(std::uint32_t cells, double size, const Vec3& origin) {
    MeshData mesh;
    for (std::uint32_t i = 0; i <= cells; ++i) {
        for (std::uint32_t j = 0; j <= cells; ++j) {
            mesh.vertices.push_back(origin + Vec3(size * i / cells, size * j / cells, 0));
        }
    }
    mesh.triangles = grid_triangles(cells);
    return mesh;
}

MeshData surface_grid(std::uint32_t columns, std::uint32_t rows, const std::function<Vec3(double, double)>& place) {
    MeshData mesh;
    for (std::uint32_t j = 0; j <= rows; ++j)
        for (std::uint32_t i = 0; i <= columns; ++i)
            mesh.vertices.push_back(place(static_cast<double>(i) / columns, static_cast<double>(j) / rows));
    const std::uint32_t stride = columns + 1;
    for (std::uint32_t j = 0; j < rows; ++j) {
        for (std::uint32_t i = 0; i < columns; ++i) {
            const std::uint32_t v = j * stride + i;
            mesh.triangles.push_back({v, v + 1, v + stride + 1});
            mesh.triangles.push_back({v, v + stride + 1, v + stride});
        }
    }
    return mesh;
}

MeshData helix_ramp(double turns, const std::function<double(double)>& height, std::uint32_t segments_per_turn) {
    const double sweep = 2 * 3.141592653589793 * turns;
    const auto columns = static_cast<std::uint32_t>(std::ceil(turns * segments_per_turn));
    return surface_grid(columns, 3, [&](double u, double v) {
        const double angle = sweep * u, radius = 1 + v;
        return Vec3(radius * std::cos(angle), radius * std::sin(angle), height(angle));
    });
}

MeshData slit_sheet(std::uint32_t cells, std::uint32_t slit) {
    MeshData mesh = surface_grid(cells, cells, [&](double u, double v) { return Vec3(cells * u, cells * v, 0); });
    const std::uint32_t stride = cells + 1, mid = cells / 2;
    std::vector<std::uint32_t> twin(mesh.vertices.size());
    for (std::uint32_t v = 0; v < twin.size(); ++v) twin[v] = v;
    for (std::uint32_t j = 0; j < slit; ++j) {  // row j of the slit line gets a twin
        twin[j * stride + mid] = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(mesh.vertices[j * stride + mid]);
    }
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t cell = t / 2, row = cell / cells, column = cell % cells;
        if (column != mid || row >= slit) continue;  // the cells right of the slit
        for (std::uint32_t& v : mesh.triangles[t]) v = twin[v];
    }
    return mesh;
}

MeshData crumpled_sheet(std::mt19937_64& rng, std::uint32_t cells, double amplitude, bool jitter) {
    MeshData mesh = grid_sheet(cells, cells, Vec3::Zero());
    for (Vec3& vertex : mesh.vertices) {
        vertex.z() = amplitude * uniform_int(rng, -1, 1);
        if (jitter) {
            vertex.x() += 0.25 * uniform_int(rng, -2, 2);
            vertex.y() += 0.25 * uniform_int(rng, -2, 2);
        }
    }
    return mesh;
}

MeshData grid_soup(std::mt19937_64& rng, std::uint32_t triangles, int extent, double scale) {
    MeshData mesh;
    for (std::uint32_t t = 0; t < triangles; ++t) {
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int corner = 0; corner < 3; ++corner) {
            mesh.vertices.emplace_back(scale * uniform_int(rng, 0, extent), scale * uniform_int(rng, 0, extent),
                                       scale * uniform_int(rng, 0, extent));
        }
        if (uniform_int(rng, 0, 15) == 0) mesh.vertices[base + 2] = mesh.vertices[base];  // a segment
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    return mesh;
}

MeshData translated(MeshData mesh, const Vec3& offset) {
    for (Vec3& vertex : mesh.vertices) vertex += offset;
    return mesh;
}

Scene random_scene(std::uint64_t seed, const RandomSceneConfig& config) {
    std::mt19937_64 rng(seed);
    std::vector<MeshData> shapes;
    std::vector<Vec3> positions;
    std::vector<Vec3> velocities;
    for (std::uint32_t o = 0; o < config.objects; ++o) {
        const auto count = static_cast<std::uint32_t>(uniform_int(rng, 4, static_cast<int>(config.max_triangles)));
        shapes.push_back(uniform_int(rng, 0, 1) == 0 ? grid_soup(rng, count, 4)
                                                     : crumpled_sheet(rng, config.sheet_cells, 1.0, true));
        positions.emplace_back(uniform_int(rng, 0, 6), uniform_int(rng, 0, 6), uniform_int(rng, 0, 3));
        velocities.emplace_back(uniform_int(rng, -2, 2), uniform_int(rng, -2, 2), uniform_int(rng, -1, 1));
    }
    std::vector<std::vector<MeshData>> frames(config.frames);
    std::vector<std::string> names;
    for (std::uint32_t o = 0; o < config.objects; ++o) names.push_back("object" + std::to_string(o));
    for (std::uint32_t f = 0; f < config.frames; ++f) {
        for (std::uint32_t o = 0; o < config.objects; ++o) {
            frames[f].push_back(translated(shapes[o], positions[o] + f * velocities[o]));
        }
    }
    Scene scene;
    scene.name = "random";
    scene.seed = seed;
    scene.source = make_memory_source(std::move(names), std::move(frames));
    return scene;
}

Frame make_frame(std::vector<MeshData> meshes) {
    std::vector<std::string> names;
    for (std::size_t o = 0; o < meshes.size(); ++o) names.push_back("object" + std::to_string(o));
    return make_memory_source(std::move(names), {std::move(meshes)})->frame(0);
}

std::vector<Frame> all_frames(const Scene& scene) {
    std::vector<Frame> frames;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) frames.push_back(scene.source->frame(f));
    return frames;
}

}  // namespace collidescope::testing
