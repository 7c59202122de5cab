// The cloth family (issue 23): cloth-like scenes where self-contact and degenerate contact
// dominate, self-collision on in all four.
//
// cloth-rest     a flat square cloth lying in the plane z = 0.3 (axis-aligned, as on a floor),
//                turning slowly in its plane: every adjacent pair is exactly coplanar, nothing
//                collides. Large: 708 x 708 vertices, 999,698 triangles.
// cloth-drape    a square cloth falling onto a sphere and draping over it (a height field over
//                its grid, so it cannot intersect itself), wrinkles growing on the hanging part;
//                it floats 2% of the radius above the sphere at first and ends 0.5% inside it,
//                so the last frames have cloth-sphere contact. Large: 460 x 460 cloth vertices.
// cloth-crumple  a long strip compressed into an accordion whose folds close up into narrow
//                near-vertical walls (x(u) = c (u - b sin ku) stays increasing, so the strip is
//                a height field over a rectilinear grid: no contact, many near misses).
//                Large: 1800 x 120 vertices, 428,162 triangles.
// cloth-slide    two sheets in the same plane z = -0.2, one turning and sliding over the other:
//                exact coplanar overlap everywhere they overlap. Large: 330 x 330 each,
//                432,964 triangles.
//
// Coordinates are float32 values like every generated scene's; the planes z = 0.3 and -0.2
// stay exact because the turns about z copy z.

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"
#include "datasets/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collidescope::datasets {
namespace {

/// p turned by `angle` about the z axis; z is copied, so a plane z = const stays exact.
Vec3 turn_about_z(const Vec3& p, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()};
}

GeneratedObject grid_object(std::string name, std::uint32_t columns, std::uint32_t rows,
                            VertexFunction vertices) {
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(grid_triangles(columns, rows), columns * rows)}};
    object.vertices = std::move(vertices);
    return object;
}

// ---- cloth-rest ------------------------------------------------------------------------

Scene make_rest(Preset preset, std::uint64_t seed) {
    const std::uint32_t n = pick(preset, 24, 201, 708);
    const std::uint32_t frames = pick(preset, 4, 20, 8);
    Random random(seed, 0xC1);
    const double turn = random.uniform(0.1, 0.3);  // radians over the animation
    auto vertices = [n, frames, turn](std::uint32_t frame, std::span<Vec3> out) {
        const double angle = turn * frame_time(frame, frames);
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i)
                out[std::size_t{j} * n + i] =
                    turn_about_z(Vec3(lerp_grid(i, n, -1, 1), lerp_grid(j, n, -1, 1), 0.3), angle);
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(grid_object("cloth", n, n, vertices));
    return family_scene("cloth-rest", preset, seed, std::move(objects), frames);
}

// ---- cloth-drape -----------------------------------------------------------------------

constexpr double k_sphere_radius = 0.6;

/// The drape's sphere: the unit sphere scaled to k_sphere_radius.
void sphere_vertices(std::uint32_t segments, std::uint32_t rings, std::span<Vec3> out) {
    unit_sphere_vertices(segments, rings, out);
    for (Vec3& p : out) p *= k_sphere_radius;
}

/// Height of the draped cloth over (x, y) with the cloth `gap` above the sphere's top: on the
/// sphere's cap (r <= r0) the sphere plus the gap, beyond it tangent and then falling faster,
/// with radial wrinkles growing away from the cap.
double draped_height(double x, double y, double gap, double wrinkle_phase) {
    const double radius = k_sphere_radius, r0 = 0.9 * radius;
    const double r = std::hypot(x, y);
    if (r <= r0) return std::sqrt(radius * radius - r * r) + gap;
    const double top = std::sqrt(radius * radius - r0 * r0);
    const double slope = r0 / top;
    const double d = r - r0;
    const double wrinkle = 0.08 * d * d * std::sin(9 * std::atan2(y, x) + wrinkle_phase);
    return top + gap - slope * d - 0.6 * d * d + wrinkle;
}

Scene make_drape(Preset preset, std::uint64_t seed) {
    const std::uint32_t n = pick(preset, 24, 201, 460);
    const std::uint32_t segments = pick(preset, 16, 64, 128), rings = pick(preset, 8, 32, 63);
    const std::uint32_t frames = pick(preset, 6, 30, 10);
    Random random(seed, 0xC2);
    const double wrinkle_phase = random.uniform(0, 2 * k_pi);
    auto cloth = [n, frames, wrinkle_phase](std::uint32_t frame, std::span<Vec3> out) {
        const double t = frame_time(frame, frames);
        const double fall = smoothstep(0, 0.7, t);
        const double gap = k_sphere_radius * (0.02 - 0.025 * smoothstep(0.6, 1, t));
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i) {
                const double x = lerp_grid(i, n, -1.5, 1.5), y = lerp_grid(j, n, -1.5, 1.5);
                const double flat = k_sphere_radius + 0.5;
                const double z = (1 - fall) * flat + fall * draped_height(x, y, gap, wrinkle_phase);
                out[std::size_t{j} * n + i] = Vec3(x, y, z);
            }
    };
    GeneratedObject sphere;
    sphere.name = "sphere";
    sphere.phases = {{0, make_topology(sphere_triangles(segments, rings), segments * rings + 2)}};
    sphere.vertices = [segments, rings](std::uint32_t, std::span<Vec3> out) {
        sphere_vertices(segments, rings, out);
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(grid_object("cloth", n, n, cloth));
    objects.push_back(std::move(sphere));
    return family_scene("cloth-drape", preset, seed, std::move(objects), frames);
}

// ---- cloth-crumple ---------------------------------------------------------------------

Scene make_crumple(Preset preset, std::uint64_t seed) {
    const std::uint32_t columns = pick(preset, 48, 600, 1800), rows = pick(preset, 12, 60, 120);
    const std::uint32_t folds = pick(preset, 4, 20, 40);
    const std::uint32_t frames = pick(preset, 6, 30, 10);
    Random random(seed, 0xC3);
    const double width_phase = random.uniform(0, 2 * k_pi);
    constexpr double length = 8, width = 0.5;
    auto vertices = [=](std::uint32_t frame, std::span<Vec3> out) {
        const double s = smoothstep(0, 1, frame_time(frame, frames));
        const double k = 2 * k_pi * folds / length;
        const double b = 0.97 * s / k;            // b k < 1: x stays increasing in u
        const double squeeze = 1 - 0.5 * s;       // the strip's ends approach each other
        const double amplitude = 0.5 * (length / folds) * (0.2 + 0.8 * s);
        for (std::uint32_t j = 0; j < rows; ++j) {
            const double v = lerp_grid(j, rows, 0, width);
            const double across = 1 + 0.15 * std::sin(2 * k_pi * v / width + width_phase);
            for (std::uint32_t i = 0; i < columns; ++i) {
                const double u = lerp_grid(i, columns, 0, length);
                out[std::size_t{j} * columns + i] =
                    Vec3(squeeze * (u - b * std::sin(k * u)), v, amplitude * across * std::cos(k * u));
            }
        }
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(grid_object("strip", columns, rows, vertices));
    return family_scene("cloth-crumple", preset, seed, std::move(objects), frames);
}

// ---- cloth-slide -----------------------------------------------------------------------

Scene make_slide(Preset preset, std::uint64_t seed) {
    const std::uint32_t n = pick(preset, 17, 141, 330);
    const std::uint32_t frames = pick(preset, 6, 30, 10);
    Random random(seed, 0xC4);
    const double turn = random.uniform(0.2, 0.5);
    const double drift = random.uniform(0.3, 0.6);
    auto lower = [n](std::uint32_t, std::span<Vec3> out) {
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i)
                out[std::size_t{j} * n + i] = Vec3(lerp_grid(i, n, -1, 1), lerp_grid(j, n, -1, 1), -0.2);
    };
    auto upper = [n, frames, turn, drift](std::uint32_t frame, std::span<Vec3> out) {
        const double t = frame_time(frame, frames);
        const double angle = 0.05 + turn * t;
        const double dx = 1.2 - 2 * drift * t, dy = 0.3 * t;
        for (std::uint32_t j = 0; j < n; ++j)
            for (std::uint32_t i = 0; i < n; ++i) {
                const Vec3 p = turn_about_z(Vec3(lerp_grid(i, n, -1, 1), lerp_grid(j, n, -1, 1), -0.2), angle);
                out[std::size_t{j} * n + i] = Vec3(p.x() + dx, p.y() + dy, p.z());
            }
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(grid_object("sheet_0", n, n, lower));
    objects.push_back(grid_object("sheet_1", n, n, upper));
    return family_scene("cloth-slide", preset, seed, std::move(objects), frames);
}

}  // namespace

Scene make_cloth_scene(std::string_view name, std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, name);
    if (name == "cloth-rest") return make_rest(preset, seed);
    if (name == "cloth-drape") return make_drape(preset, seed);
    if (name == "cloth-crumple") return make_crumple(preset, seed);
    if (name == "cloth-slide") return make_slide(preset, seed);
    throw InputError("unknown cloth scene '" + std::string(name) + "'");
}

}  // namespace collidescope::datasets
