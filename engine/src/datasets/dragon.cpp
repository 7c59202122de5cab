// Data set E (thesis 3.3 Figure 3.9, and 5.2.1 Figures 5.10-5.13): two Stanford dragons
// exploding into each other, at four speeds.
//
// The dragons (normalised to a bounding box whose longest side, along x, is 1) start
// interpenetrating: the second is the first turned half a turn about the vertical y axis and
// moved 0.45 along x and 0.08 along z. Frame 0 shows them intact (the file's shared vertices);
// from frame 1 on each is a triangle soup (three vertices per triangle; the topology changes
// once) whose triangles fly away from their dragon's centre, each along its own jittered
// direction at its own speed, spinning about a random axis. The flight eases out: the
// distance covered is 1 - (1 - s)^2 of the final one at s = frame / (frames - 1), so the
// fragments are fast at first and slow down, and the two clouds of fragments mix, giving
// inter-object collisions throughout. E1 to E4 run the same explosion over 25, 50, 100 and 200
// frames: E1 deforms fastest per frame, E4 slowest.

#include "datasets/decimate.hpp"
#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"
#include "datasets/mesh_assets.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

// How each triangle of one dragon flies, drawn from the seed.
struct Explosion {
    std::vector<Vec3> velocity;      // final displacement of the triangle's centroid
    std::vector<Vec3> spin_axis;
    std::vector<double> spin_angle;  // final rotation about the centroid (radians)
};

Vec3 centroid_of(const MeshData& mesh, const TriIndices& tri) {
    return (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3;
}

// Each triangle flies away from `center` along its centroid's direction, jittered.
Explosion random_explosion(Random& random, const MeshData& dragon, const Vec3& center) {
    Explosion explosion;
    for (const TriIndices& tri : dragon.triangles) {
        Vec3 direction = centroid_of(dragon, tri) - center + 0.3 * random.unit_vector();
        direction.normalize();
        explosion.velocity.push_back(random.uniform(0.4, 1.2) * direction);
        explosion.spin_axis.push_back(random.unit_vector());
        explosion.spin_angle.push_back(random.uniform(1, 4) * k_pi);
    }
    return explosion;
}

// The soup at ease `e` in [0, 1] (the fraction of the final displacement).
void exploded_vertices(const MeshData& dragon, const Explosion& explosion, double e,
                       std::span<Vec3> out) {
    for (std::size_t i = 0; i < dragon.triangles.size(); ++i) {
        const TriIndices& tri = dragon.triangles[i];
        const Vec3 centroid = centroid_of(dragon, tri);
        const Eigen::Matrix3d spin =
            Eigen::AngleAxisd(e * explosion.spin_angle[i], explosion.spin_axis[i])
                .toRotationMatrix();
        const Vec3 moved = centroid + e * explosion.velocity[i];
        for (int k = 0; k < 3; ++k) {
            out[3 * i + k] = moved + spin * (dragon.vertices[tri[k]] - centroid);
        }
    }
}

// `dragon` is already placed in the scene, its bounding box centred on `center`.
GeneratedObject exploding_dragon(std::shared_ptr<const MeshData> dragon, const Vec3& center,
                                 Random& random, std::uint32_t frames, std::string name) {
    auto explosion = std::make_shared<const Explosion>(random_explosion(random, *dragon, center));
    const auto triangles = static_cast<std::uint32_t>(dragon->triangles.size());
    const auto vertices = static_cast<std::uint32_t>(dragon->vertices.size());
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(dragon->triangles, vertices)},
                     {1, make_topology(soup_triangles(triangles), 3 * triangles)}};
    object.vertices = [dragon, explosion, frames](std::uint32_t frame, std::span<Vec3> out) {
        if (frame == 0) {
            std::copy(dragon->vertices.begin(), dragon->vertices.end(), out.begin());
            return;
        }
        const double s = static_cast<double>(frame) / (frames - 1);
        exploded_vertices(*dragon, *explosion, 1 - (1 - s) * (1 - s), out);
    };
    return object;
}

// `dragon` turned by `rotation` about its centre, then moved by `offset`.
std::shared_ptr<const MeshData> placed(const MeshData& dragon, const Eigen::Matrix3d& rotation,
                                       const Vec3& offset) {
    auto result = std::make_shared<MeshData>(dragon);
    for (Vec3& v : result->vertices) v = rotation * v + offset;
    return result;
}

MeshData dragon_at(Preset preset) {
    if (preset == Preset::Small) {
        MeshData dragon = load_dragon(DragonResolution::Res4);
        center_and_scale(dragon, 1.0);
        return decimate(dragon, 20);
    }
    MeshData dragon =
        load_dragon(preset == Preset::Default ? DragonResolution::Res3 : DragonResolution::Full);
    center_and_scale(dragon, 1.0);
    return dragon;
}

std::uint32_t explosion_frames(int speed, Preset preset) {
    constexpr std::array<std::uint32_t, 4> k_small = {6, 10, 16, 24};
    constexpr std::array<std::uint32_t, 4> k_full = {25, 50, 100, 200};
    return (preset == Preset::Small ? k_small : k_full)[static_cast<std::size_t>(speed - 1)];
}

}  // namespace

Scene make_scene_E(int speed, std::string_view preset_text, std::uint64_t seed) {
    // Appended rather than `"E" + std::to_string(speed)`, which trips GCC 12's bogus
    // -Wrestrict warning (GCC bug 105329).
    std::string name = "E";
    name += std::to_string(speed);
    if (speed < 1 || speed > 4) {
        throw InputError("scene " + name + ": no such speed (E1 to E4)");
    }
    const Preset preset = parse_preset(preset_text, name);
    const std::uint32_t frames = explosion_frames(speed, preset);
    const MeshData dragon = dragon_at(preset);
    const Vec3 offset(0.45, 0, 0.08);
    const Eigen::Matrix3d half_turn = Eigen::AngleAxisd(k_pi, Vec3::UnitY()).toRotationMatrix();
    // Same seed stream for every speed: E1 to E4 differ only in how many frames they take.
    Random random(seed, 0xE);
    std::vector<GeneratedObject> objects;
    objects.push_back(exploding_dragon(placed(dragon, Eigen::Matrix3d::Identity(), Vec3::Zero()),
                                       Vec3::Zero(), random, frames, "dragon_0"));
    objects.push_back(exploding_dragon(placed(dragon, half_turn, offset), offset, random, frames,
                                       "dragon_1"));
    return {name, preset_name(preset), seed, false,
            make_generated_source(std::move(objects), frames)};
}

}  // namespace collidescope::datasets
