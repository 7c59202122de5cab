// Data set D (thesis 2.4 and 5.2.1, Figure 5.9): a BART-like animation.
//
// BART (the Benchmark for Animated Ray Tracing, Lext, Assarsson and Moller 2001), whose museum
// scene the thesis used, is not available here, so this is an analogue with the property the
// thesis relies on: incoherent first, coherent later. Two linked tori (major radius 0.5, tube
// radius about 0.15, each passing through the other's centre) are the assembled shape. For
// the first half of the frames each torus is a triangle soup (every triangle its own three
// vertices): each triangle starts up to 0.8 away from its place, spins about a random axis
// and swirls in toward it, the scatter shrinking linearly to zero at the middle frame; the two
// soups overlap, so many triangles of the two objects intersect (in all but the last soup
// frames, when the triangles are nearly home). From the middle frame on, the topology switches
// once to the shared-vertex tori, which ripple, slide along themselves and turn slowly as a
// pair; linked tori whose tube radii stay below 0.17 keep a gap of at least 0.16, so the
// second half is collision-free.

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

constexpr double k_major = 0.5;
constexpr double k_tube = 0.15;

// One torus of the assembled shape, and how it moves once assembled.
struct TorusShape {
    std::uint32_t columns = 0;  // around the main axis
    std::uint32_t rows = 0;     // around the tube
    Vec3 center;
    Vec3 axis, e1, e2;          // orthonormal frame, axis = symmetry axis
    Vec3 pair_axis;             // both tori turn about this axis together
    double ripple_phase = 0, slide = 0;

    // Vertex (i, j) at animation time t in [0, 1].
    Vec3 vertex(std::uint32_t i, std::uint32_t j, const Eigen::Matrix3d& turn, double t) const {
        const double alpha = 2 * k_pi * i / columns + slide * t;
        const double beta = 2 * k_pi * j / rows;
        const double tube = k_tube * (1 + 0.12 * std::sin(3 * alpha + 4 * k_pi * t + ripple_phase));
        const Vec3 radial = std::cos(alpha) * e1 + std::sin(alpha) * e2;
        const Vec3 local =
            (k_major + tube * std::cos(beta)) * radial + tube * std::sin(beta) * axis;
        return turn * (center + local);
    }
    Eigen::Matrix3d turn(double t) const {
        return Eigen::AngleAxisd(0.5 * k_pi * t, pair_axis).toRotationMatrix();
    }
    void vertices(double t, std::span<Vec3> out) const {
        const Eigen::Matrix3d rotation = turn(t);
        for (std::uint32_t j = 0; j < rows; ++j) {
            for (std::uint32_t i = 0; i < columns; ++i) {
                out[std::size_t{j} * columns + i] = vertex(i, j, rotation, t);
            }
        }
    }
};

// Where each soup triangle flies before it settles, drawn from the seed.
struct SoupFlight {
    std::vector<Vec3> offset;       // scatter at s = 0
    std::vector<Vec3> swirl;        // second scatter direction
    std::vector<Vec3> spin_axis;
    std::vector<double> spin_angle;
    std::vector<double> swirl_rate;
};

SoupFlight random_flight(Random& random, std::size_t triangles) {
    SoupFlight flight;
    for (std::size_t i = 0; i < triangles; ++i) {
        flight.offset.push_back(random.in_ball(0.8));
        flight.swirl.push_back(random.in_ball(0.4));
        flight.spin_axis.push_back(random.unit_vector());
        flight.spin_angle.push_back(random.uniform(2, 6) * k_pi);
        flight.swirl_rate.push_back(random.uniform(1, 3) * k_pi);
    }
    return flight;
}

// The soup at s in [0, 1): each triangle's corners of `target` moved by its flight.
void soup_vertices(const SoupFlight& flight, const std::vector<TriIndices>& triangles,
                   const std::vector<Vec3>& target, double s, std::span<Vec3> out) {
    const double scatter = 1 - s;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const TriIndices& tri = triangles[i];
        const Vec3 centroid = (target[tri[0]] + target[tri[1]] + target[tri[2]]) / 3;
        const double swirl = flight.swirl_rate[i] * s;
        const Vec3 shift = scatter * (std::cos(swirl) * flight.offset[i] +
                                      std::sin(swirl) * flight.swirl[i]);
        const Eigen::Matrix3d spin =
            Eigen::AngleAxisd(scatter * flight.spin_angle[i], flight.spin_axis[i])
                .toRotationMatrix();
        for (int k = 0; k < 3; ++k) {
            out[3 * i + k] = centroid + shift + spin * (target[tri[k]] - centroid);
        }
    }
}

GeneratedObject torus_object(const TorusShape& shape, Random& random, std::uint32_t frames,
                             std::string name) {
    auto triangles = std::make_shared<const std::vector<TriIndices>>(
        torus_triangles(shape.columns, shape.rows));
    const auto count = static_cast<std::uint32_t>(triangles->size());
    auto flight = std::make_shared<const SoupFlight>(random_flight(random, count));
    const std::uint32_t half = frames / 2;
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(soup_triangles(count), 3 * count)},
                     {half, make_topology(*triangles, shape.columns * shape.rows)}};
    object.vertices = [shape, triangles, flight, frames, half](std::uint32_t frame,
                                                               std::span<Vec3> out) {
        const double t = static_cast<double>(frame) / (frames - 1);
        if (frame >= half) {
            shape.vertices(t, out);
            return;
        }
        std::vector<Vec3> target(std::size_t{shape.columns} * shape.rows);
        shape.vertices(t, target);
        soup_vertices(*flight, *triangles, target, static_cast<double>(frame) / half, out);
    };
    return object;
}

// The two linked tori: the first in the xy plane around the origin, the second in the xz
// plane around (0.5, 0, 0); each circle of centres passes through the other's centre.
std::array<TorusShape, 2> linked_tori(Random& random, std::uint32_t columns, std::uint32_t rows) {
    const Vec3 pair_axis = random.unit_vector();
    std::array<TorusShape, 2> tori;
    for (TorusShape& torus : tori) {
        torus.columns = columns;
        torus.rows = rows;
        torus.pair_axis = pair_axis;
        torus.ripple_phase = random.uniform(0, 2 * k_pi);
        torus.slide = random.uniform(-1, 1) * k_pi;
    }
    tori[0].center = Vec3::Zero();
    tori[0].axis = Vec3::UnitZ(), tori[0].e1 = Vec3::UnitX(), tori[0].e2 = Vec3::UnitY();
    tori[1].center = Vec3(k_major, 0, 0);
    tori[1].axis = Vec3::UnitY(), tori[1].e1 = Vec3::UnitZ(), tori[1].e2 = Vec3::UnitX();
    return tori;
}

}  // namespace

Scene make_scene_D(std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, "D");
    const std::uint32_t columns =
        preset == Preset::Small ? 32 : preset == Preset::Default ? 160 : 400;
    const std::uint32_t rows = preset == Preset::Small ? 16 : preset == Preset::Default ? 64 : 160;
    const std::uint32_t frames = preset == Preset::Small ? 16 : 200;
    Random random(seed, 0xD);
    const std::array<TorusShape, 2> tori = linked_tori(random, columns, rows);
    std::vector<GeneratedObject> objects;
    objects.push_back(torus_object(tori[0], random, frames, "torus_0"));
    objects.push_back(torus_object(tori[1], random, frames, "torus_1"));
    return {"D", preset_name(preset), seed, false,
            make_generated_source(std::move(objects), frames)};
}

}  // namespace collidescope::datasets
