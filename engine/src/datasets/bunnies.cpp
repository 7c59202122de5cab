// Data set A (thesis 5.2.1, Figure 5.6): two Stanford bunnies under rigid motion.
//
// The bunnies (normalised to a bounding box whose longest side is 1) start 1.9 apart along
// x, each spinning about its own random axis, glide toward each other along x with a small
// random offset in y and z, pass through each other in the middle of the animation and end
// 1.9 apart on swapped sides. No bunny vertex lies farther than 0.68 from its box centre, so
// the first and last frames are free of collisions; around the middle frame the bunnies
// interpenetrate.

#include "datasets/decimate.hpp"
#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"
#include "datasets/mesh_assets.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

constexpr double k_half_gap = 0.95;  // start and end centre distance from the origin along x

// One bunny's motion, drawn from the seed.
struct RigidMotion {
    Eigen::Matrix3d start_orientation;
    Vec3 spin_axis;
    double spin_angle = 0;  // radians over the whole animation
    double side = 1;        // +1 starts at +x, -1 at -x
    Vec3 offset;            // constant y, z offset of the path (x component 0)

    Vec3 center(double t) const {
        return Vec3(side * k_half_gap * std::cos(std::numbers::pi * t), 0, 0) + offset;
    }
    Eigen::Matrix3d rotation(double t) const {
        return Eigen::AngleAxisd(spin_angle * t, spin_axis).toRotationMatrix() *
               start_orientation;
    }
};

RigidMotion random_motion(Random& random, double side) {
    RigidMotion motion;
    const Vec3 axis = random.unit_vector();
    const double angle = random.uniform(0, 2 * std::numbers::pi);
    motion.start_orientation = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    motion.spin_axis = random.unit_vector();
    motion.spin_angle = 2 * std::numbers::pi * random.uniform(0.75, 1.5);
    motion.side = side;
    const double y = random.uniform(0.05, 0.2);
    const double z = random.uniform(-0.1, 0.1);
    motion.offset = Vec3(0, side * y, z);
    return motion;
}

MeshData bunny_at(Preset preset) {
    MeshData bunny = load_bunny();
    center_and_scale(bunny, 1.0);
    switch (preset) {
        case Preset::Small: return decimate(bunny, 16);
        case Preset::Default: return decimate(bunny, 64);
        case Preset::Large: return bunny;
    }
    return bunny;
}

GeneratedObject moving_bunny(const MeshData& bunny, const RigidMotion& motion,
                             std::uint32_t frames, std::string name) {
    auto rest = std::make_shared<const std::vector<Vec3>>(bunny.vertices);
    const auto vertex_count = static_cast<std::uint32_t>(bunny.vertices.size());
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(bunny.triangles, vertex_count)}};
    object.vertices = [rest, motion, frames](std::uint32_t frame, std::span<Vec3> out) {
        const double t = static_cast<double>(frame) / (frames - 1);
        const Eigen::Matrix3d rotation = motion.rotation(t);
        const Vec3 center = motion.center(t);
        for (std::size_t v = 0; v < out.size(); ++v) out[v] = rotation * (*rest)[v] + center;
    };
    return object;
}

}  // namespace

Scene make_scene_A(std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, "A");
    const MeshData bunny = bunny_at(preset);
    const std::uint32_t frames = preset == Preset::Small ? 16 : 200;
    Random random(seed, 0xA);
    const RigidMotion left = random_motion(random, -1);
    const RigidMotion right = random_motion(random, +1);
    std::vector<GeneratedObject> objects;
    objects.push_back(moving_bunny(bunny, left, frames, "bunny_0"));
    objects.push_back(moving_bunny(bunny, right, frames, "bunny_1"));
    return {"A", preset_name(preset), seed, false,
            make_generated_source(std::move(objects), frames)};
}

}  // namespace collidescope::datasets
