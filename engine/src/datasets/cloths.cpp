// Data set B (thesis 5.2.1, Figure 5.7): two waving cloths deforming and rotating into each
// other.
//
// Each cloth is a square grid sheet, side 2, waving like a flag (a travelling wave whose
// amplitude grows from one edge, plus a weaker cross wave). The cloths start parallel, 1 apart
// along z, and over the first half of the animation close that gap while tilting toward each
// other about x and spinning in their planes in opposite directions; from then on their waves
// cut through each other: many true collisions. In the second half each cloth also folds its
// free edge (u > 0.4) over onto itself, half a turn about the line u = 0.4; the folded flap's
// waves cross the sheet's, so there are true self-collisions too (self-collision is on). The
// first frames are collision-free (the waves reach at most 0.24 from a sheet's plane).

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"
#include "datasets/shapes.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

constexpr double k_fold_line = 0.4;  // the flap u > 0.4 folds over in the second half

// One cloth's waves and placement, drawn from the seed.
struct ClothMotion {
    double side = 1;             // -1: the lower cloth, +1: the upper one
    double amplitude = 0.12;     // main wave amplitude at the free edge
    double wave_number = 0;      // main wave, along u (radians per unit)
    double wave_phase = 0;
    double cross_number = 0;     // cross wave, along v
    double cross_phase = 0;
    double spin = 0;             // in-plane rotation over the animation (radians)

    double gap(double t) const { return 0.5 * (1 - smoothstep(0, 0.5, t)); }
    double fold(double t) const { return k_pi * smoothstep(0.5, 0.95, t); }
    double tilt(double t) const { return 0.3 * std::sin(k_pi * t); }

    Eigen::Matrix3d placement(double t) const {
        return (Eigen::AngleAxisd(side * tilt(t), Vec3::UnitX()) *
                Eigen::AngleAxisd(side * spin * t, Vec3::UnitZ()))
            .toRotationMatrix();
    }
};

ClothMotion random_cloth(Random& random, double side) {
    ClothMotion cloth;
    cloth.side = side;
    cloth.amplitude = random.uniform(0.10, 0.14);
    cloth.wave_number = k_pi * random.uniform(2.0, 3.0);
    cloth.wave_phase = random.uniform(0, 2 * k_pi);
    cloth.cross_number = k_pi * random.uniform(1.0, 2.0);
    cloth.cross_phase = random.uniform(0, 2 * k_pi);
    cloth.spin = random.uniform(0.3, 0.6) * k_pi;
    return cloth;
}

// Fills the (n x n) sheet of `cloth` at animation time t in [0, 1].
void cloth_vertices(const ClothMotion& cloth, std::uint32_t n, double t, std::span<Vec3> out) {
    const double travel = 4 * k_pi * t;  // the waves travel two periods over the animation
    // The grid is square: index i has the same coordinate along u and along v.
    std::vector<double> coord(n);
    std::vector<double> along_u(n);  // main wave at u = coord[i]
    std::vector<double> along_v(n);  // cross wave at v = coord[j]
    for (std::uint32_t i = 0; i < n; ++i) {
        const double c = -1 + 2 * static_cast<double>(i) / (n - 1);
        coord[i] = c;
        const double growth = 0.25 + 0.5 * (c + 1);  // the flag's free edge is at u = 1
        along_u[i] = cloth.amplitude * growth *
                     std::sin(cloth.wave_number * c - travel + cloth.wave_phase);
        along_v[i] = 0.4 * cloth.amplitude *
                     std::sin(cloth.cross_number * c + 0.5 * travel + cloth.cross_phase);
    }
    const Eigen::Matrix3d placement = cloth.placement(t);
    const Vec3 shift(0, 0, cloth.side * cloth.gap(t));
    const double fold_cos = std::cos(cloth.fold(t));
    const double fold_sin = std::sin(cloth.fold(t));
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            double u = coord[i];
            double w = along_u[i] + along_v[j];
            if (u > k_fold_line) {  // rotate the flap about the fold line (u = 0.4, w = 0)
                const double d = u - k_fold_line;
                u = k_fold_line + d * fold_cos - w * fold_sin;
                w = d * fold_sin + w * fold_cos;
            }
            out[std::size_t{j} * n + i] = placement * Vec3(u, coord[j], w) + shift;
        }
    }
}

GeneratedObject cloth_object(const ClothMotion& cloth, std::uint32_t n, std::uint32_t frames,
                             std::string name) {
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(grid_triangles(n, n), n * n)}};
    object.vertices = [cloth, n, frames](std::uint32_t frame, std::span<Vec3> out) {
        cloth_vertices(cloth, n, static_cast<double>(frame) / (frames - 1), out);
    };
    return object;
}

}  // namespace

Scene make_scene_B(std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, "B");
    const std::uint32_t n = preset == Preset::Small ? 24 : preset == Preset::Default ? 101 : 256;
    const std::uint32_t frames = preset == Preset::Small ? 16 : 200;
    Random random(seed, 0xB);
    const ClothMotion lower = random_cloth(random, -1);
    const ClothMotion upper = random_cloth(random, +1);
    std::vector<GeneratedObject> objects;
    objects.push_back(cloth_object(lower, n, frames, "cloth_0"));
    objects.push_back(cloth_object(upper, n, frames, "cloth_1"));
    return {"B", preset_name(preset), seed, true,
            make_generated_source(std::move(objects), frames)};
}

}  // namespace collidescope::datasets
