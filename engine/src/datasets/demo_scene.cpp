// The demo scene: a torus spinning about z at the origin, and a square sheet, waving, that
// travels along x from one side of the torus to the other. The sheet starts and ends clear of
// the torus (its box and the torus's box apart), and cuts through the ring in the middle.

#include "datasets/demo_scene.hpp"

#include "collidescope/error.hpp"

#include <cmath>
#include <numbers>

namespace collidescope {
namespace {

constexpr double k_torus_major_radius = 1.0;
constexpr double k_torus_minor_radius = 0.3;
constexpr double k_sheet_half_size = 1.6;
constexpr double k_sheet_travel = 2.6;  ///< the sheet moves from x = -2.6 to x = +2.6
constexpr double k_wave_amplitude = 0.2;

// Quads (i, j) of a grid of `rows` x `columns` vertices, two triangles each. With `wrap`,
// the last row and column connect back to the first (a torus).
std::vector<TriIndices> grid_triangles(std::uint32_t rows, std::uint32_t columns, bool wrap) {
    std::vector<TriIndices> triangles;
    const std::uint32_t quad_rows = wrap ? rows : rows - 1;
    const std::uint32_t quad_columns = wrap ? columns : columns - 1;
    for (std::uint32_t i = 0; i < quad_rows; ++i) {
        for (std::uint32_t j = 0; j < quad_columns; ++j) {
            const std::uint32_t v00 = i * columns + j;
            const std::uint32_t v01 = i * columns + (j + 1) % columns;
            const std::uint32_t v10 = ((i + 1) % rows) * columns + j;
            const std::uint32_t v11 = ((i + 1) % rows) * columns + (j + 1) % columns;
            triangles.push_back({v00, v10, v11});
            triangles.push_back({v00, v11, v01});
        }
    }
    return triangles;
}

// The torus (axis y) turned by `angle` radians about z.
MeshData torus(const DemoConfig& config, double angle) {
    MeshData mesh;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    for (std::uint32_t i = 0; i < config.torus_major; ++i) {
        const double phi = 2 * std::numbers::pi * i / config.torus_major;
        for (std::uint32_t j = 0; j < config.torus_minor; ++j) {
            const double psi = 2 * std::numbers::pi * j / config.torus_minor;
            const double ring = k_torus_major_radius + k_torus_minor_radius * std::cos(psi);
            const Vec3 p(ring * std::cos(phi), k_torus_minor_radius * std::sin(psi),
                         ring * std::sin(phi));
            mesh.vertices.emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z());
        }
    }
    mesh.triangles = grid_triangles(config.torus_major, config.torus_minor, true);
    return mesh;
}

// The sheet (normal x) centred at x = `offset`, its wave at `phase` radians.
MeshData sheet(const DemoConfig& config, double offset, double phase) {
    MeshData mesh;
    const std::uint32_t side = config.sheet_cells + 1;
    for (std::uint32_t i = 0; i < side; ++i) {
        const double y = -k_sheet_half_size + 2 * k_sheet_half_size * i / config.sheet_cells;
        for (std::uint32_t j = 0; j < side; ++j) {
            const double z = -k_sheet_half_size + 2 * k_sheet_half_size * j / config.sheet_cells;
            const double wave = k_wave_amplitude * std::sin(2 * std::numbers::pi * z / k_sheet_half_size + phase) *
                                std::cos(std::numbers::pi * y / (2 * k_sheet_half_size));
            mesh.vertices.emplace_back(offset + wave, y, z);
        }
    }
    mesh.triangles = grid_triangles(side, side, false);
    return mesh;
}

}  // namespace

std::vector<std::string> demo_presets() { return {"default", "small"}; }

DemoConfig demo_config(const std::string& preset) {
    if (preset == "default") return {};
    if (preset == "small") return {24, 16, 8, 10};
    throw InputError("scene 'demo': unknown preset '" + preset + "' (known: default, small)");
}

Scene make_demo_scene(const DemoConfig& config, const std::string& preset) {
    std::vector<std::vector<MeshData>> frames;
    for (std::uint32_t f = 0; f < config.frames; ++f) {
        const double t = config.frames > 1 ? static_cast<double>(f) / (config.frames - 1) : 0.0;
        frames.push_back({torus(config, std::numbers::pi * t),
                          sheet(config, k_sheet_travel * (2 * t - 1), 4 * std::numbers::pi * t)});
    }
    Scene scene;
    scene.name = "demo";
    scene.preset = preset;
    scene.self_collision = false;
    scene.source = make_memory_source({"torus", "sheet"}, std::move(frames));
    return scene;
}

}  // namespace collidescope
