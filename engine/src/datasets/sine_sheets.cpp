// Data set C (thesis 5.1 and 5.2.1, Figure 5.8): two sheets deformed by sine waves, in very
// close proximity, rotating as a pair.
//
// Both sheets are height fields z = h(x, y, t) over the same square grid (side 2) with the
// same triangulation; the upper one floats a gap of 0.3 grid cells above the lower one, so
// almost every triangle's box overlaps the boxes of the triangles facing it (near misses,
// where AABB culling does poorly). Over one triangulation the vertical distance between the
// sheets is linear on each triangle, so the sheets meet only where it reaches zero at a
// vertex: a Gaussian dent wandering over the upper sheet, whose depth swings between 0.6 and
// 1.5 gaps, pushes it through the lower sheet in some frames (a few colliding pairs around the
// dent) and not in others (none). The pair rotates about z and y, so the best view axis
// changes during the animation (thesis 5.1.2). Self-collision off: a height field cannot
// intersect itself.

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

constexpr double k_amplitude = 0.15;
constexpr double k_dent_width = 0.15;

// The shared sine field, the dent and the pair's rotation, drawn from the seed.
struct SineField {
    std::uint32_t n = 0;  // vertices per side
    double gap = 0;       // 0.3 cells
    double wave_x = 0, wave_y = 0, phase_x = 0, phase_y = 0;
    double dent_phase = 0, dent_rate = 0, path_phase = 0;
    double turn_z = 0, turn_y = 0;

    double coordinate(std::uint32_t i) const { return -1 + 2 * static_cast<double>(i) / (n - 1); }
    double dent_depth(double t) const {
        const double s = std::sin(dent_rate * k_pi * t + dent_phase);
        return gap * (0.6 + 0.9 * s * s);
    }
    Vec3 dent_center(double t) const {
        const double a = 2 * k_pi * t + path_phase;
        return {0.5 * std::cos(a), 0.5 * std::sin(a), 0};
    }
    Eigen::Matrix3d rotation(double t) const {
        return (Eigen::AngleAxisd(turn_z * t, Vec3::UnitZ()) *
                Eigen::AngleAxisd(turn_y * t, Vec3::UnitY()))
            .toRotationMatrix();
    }
};

SineField random_field(Random& random, std::uint32_t n) {
    SineField field;
    field.n = n;
    field.gap = 0.3 * 2.0 / (n - 1);
    field.wave_x = k_pi * random.uniform(1.5, 2.5);
    field.wave_y = k_pi * random.uniform(1.5, 2.5);
    field.phase_x = random.uniform(0, 2 * k_pi);
    field.phase_y = random.uniform(0, 2 * k_pi);
    field.dent_phase = random.uniform(0, k_pi);
    field.dent_rate = random.uniform(2.5, 3.5);
    field.path_phase = random.uniform(0, 2 * k_pi);
    field.turn_z = k_pi * random.uniform(0.5, 1.0);
    field.turn_y = k_pi * random.uniform(0.5, 0.75);
    return field;
}

// Sheet `upper` (0 or 1) of `field` at animation time t in [0, 1].
void sheet_vertices(const SineField& field, bool upper, double t, std::span<Vec3> out) {
    const std::uint32_t n = field.n;
    const double travel = 3 * k_pi * t;  // the waves travel 1.5 periods over the animation
    std::vector<double> sine_x(n);
    std::vector<double> sine_y(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        sine_x[i] = std::sin(field.wave_x * field.coordinate(i) + travel + field.phase_x);
        sine_y[i] = std::sin(field.wave_y * field.coordinate(i) + 0.5 * travel + field.phase_y);
    }
    const Eigen::Matrix3d rotation = field.rotation(t);
    const double depth = field.dent_depth(t);
    const Vec3 dent = field.dent_center(t);
    const double inv_width2 = 1 / (k_dent_width * k_dent_width);
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double x = field.coordinate(i);
            const double y = field.coordinate(j);
            double z = k_amplitude * sine_x[i] * sine_y[j];
            if (upper) {
                const double d2 = (x - dent.x()) * (x - dent.x()) + (y - dent.y()) * (y - dent.y());
                z += field.gap - depth * std::exp(-d2 * inv_width2);
            }
            out[std::size_t{j} * n + i] = rotation * Vec3(x, y, z);
        }
    }
}

GeneratedObject sheet_object(const SineField& field, bool upper, std::uint32_t frames) {
    GeneratedObject object;
    object.name = upper ? "sheet_1" : "sheet_0";
    object.phases = {{0, make_topology(grid_triangles(field.n, field.n), field.n * field.n)}};
    object.vertices = [field, upper, frames](std::uint32_t frame, std::span<Vec3> out) {
        sheet_vertices(field, upper, static_cast<double>(frame) / (frames - 1), out);
    };
    return object;
}

}  // namespace

Scene make_scene_C(std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, "C");
    const std::uint32_t n = preset == Preset::Small ? 24 : preset == Preset::Default ? 101 : 256;
    const std::uint32_t frames = preset == Preset::Small ? 16 : 200;
    Random random(seed, 0xC);
    const SineField field = random_field(random, n);
    std::vector<GeneratedObject> objects;
    objects.push_back(sheet_object(field, false, frames));
    objects.push_back(sheet_object(field, true, frames));
    return {"C", preset_name(preset), seed, false,
            make_generated_source(std::move(objects), frames)};
}

}  // namespace collidescope::datasets
