// The contact family (issue 37): dense contact, made as an implicit solver leaves it (every
// surface kept a small gap from its neighbours, so boxes overlap everywhere and few triangles
// touch) and as coplanar overlap (exact). Self-collision on in all five.
//
// contact-layers   three cloth layers wrapped over a breathing sphere, each a gap of 0.2% of
//                  the radius above the one below, wrinkled by less than half the gap; a dent
//                  moving over the outer layer pushes it through the two below (real contact
//                  in a small region). Large: 3 x 260 x 260 cloth vertices, 418,614 triangles.
// contact-spheres  a pile of soft spheres on a jittered lattice, squeezed together over the
//                  animation: where two spheres meet each is flattened onto a plane half a gap
//                  from their mid-plane, so neighbours face each other as parallel flat patches
//                  a gap apart. Large: 48 spheres of 80 x 40, 307,200 triangles.
// contact-rods     plied yarn: 3 to 7 tubes twisted about one axis, neighbours a gap apart in
//                  every horizontal section, the twist tightening over the animation (the
//                  sections are horizontal, not normal to the tubes: where the twist is
//                  steep, neighbours come closer than the gap, and can touch).
//                  Large: 7 tubes of 48 x 700, 469,728 triangles.
// contact-rollers  a soft ellipsoid drawn between two turning rollers that squeeze it: where a
//                  roller presses, the body's surface follows the roller's a gap outside it.
//                  Large: 500 x 250 body, two 160 x 200 rollers, 377,360 triangles.
// coplanar-stack   four square patches in one plane z = 0.1 (exact: coordinates copied),
//                  overlapping pairwise and sliding and turning in the plane: coplanar overlap
//                  with every neighbour. Large: 4 x 240 x 240, 456,968 triangles.
//
// Coordinates are float32 values like every generated scene's.

#include "datasets/generated_source.hpp"
#include "datasets/generators.hpp"
#include "datasets/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace collidescope::datasets {
namespace {

std::uint32_t frames_of(Preset preset) { return pick(preset, 5, 20, 8); }

GeneratedObject object_of(std::string name, std::vector<TriIndices> triangles, std::uint32_t vertices,
                          VertexFunction place) {
    GeneratedObject object;
    object.name = std::move(name);
    object.phases = {{0, make_topology(std::move(triangles), vertices)}};
    object.vertices = std::move(place);
    return object;
}

/// Places a deformed sphere: `out[v]` from the unit sphere's vertex `unit[v]` at `frame`.
using SpherePlacement = std::function<void(std::uint32_t frame, std::span<const Vec3> unit, std::span<Vec3> out)>;

/// A UV sphere object placed per frame by `place`.
GeneratedObject sphere_object(std::string name, std::uint32_t segments, std::uint32_t rings, SpherePlacement place) {
    const std::uint32_t count = segments * rings + 2;
    std::vector<Vec3> unit(count);
    unit_sphere_vertices(segments, rings, unit);
    return object_of(std::move(name), sphere_triangles(segments, rings), count,
                     [unit = std::move(unit), place = std::move(place)](std::uint32_t frame, std::span<Vec3> out) {
                         place(frame, unit, out);
                     });
}

// ---- contact-layers --------------------------------------------------------------------

Scene make_layers(Preset preset, std::uint64_t seed) {
    const std::uint32_t n = pick(preset, 12, 100, 260);
    const std::uint32_t segments = pick(preset, 16, 64, 128), rings = pick(preset, 8, 32, 63);
    const std::uint32_t frames = frames_of(preset);
    constexpr double radius = 0.5, gap = 0.002 * radius, cap = 1.15;  // cap: polar half-width
    Random random(seed, 0xD1);
    const double phase = random.uniform(0, 2 * k_pi);
    const double dent_start = random.uniform(0, 2 * k_pi);
    const auto breathing = [frames](std::uint32_t frame) {
        return radius * (1 + 0.02 * std::sin(2 * k_pi * frame_time(frame, frames)));
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(sphere_object("body", segments, rings,
                                    [breathing](std::uint32_t frame, std::span<const Vec3> unit, std::span<Vec3> out) {
        for (std::size_t v = 0; v < unit.size(); ++v) out[v] = breathing(frame) * unit[v];
    }));
    for (std::uint32_t layer = 0; layer < 3; ++layer) {
        auto place = [=](std::uint32_t frame, std::span<Vec3> out) {
            const double t = frame_time(frame, frames);
            const double base = breathing(frame) + (layer + 1) * gap;
            // The dent: a bump on the outer layer, 2.6 gaps deep, moving around the cap.
            const double dent_azimuth = dent_start + 2 * k_pi * t, dent_polar = 0.6 * cap;
            const Vec3 dent(std::sin(dent_polar) * std::cos(dent_azimuth), std::sin(dent_polar) * std::sin(dent_azimuth),
                            std::cos(dent_polar));
            for (std::uint32_t j = 0; j < n; ++j)
                for (std::uint32_t i = 0; i < n; ++i) {
                    const double u = lerp_grid(i, n, -1, 1), v = lerp_grid(j, n, -1, 1);
                    const double polar = cap * std::hypot(u, v) / std::sqrt(2.0), azimuth = std::atan2(v, u);
                    const Vec3 d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
                    // Wrinkles of each layer's own, under half a gap: the layers never meet by them.
                    const double wrinkle = 0.45 * gap * std::sin(23 * u + 17 * v + phase * (layer + 1) + 3 * t) *
                                           std::cos(19 * v - 11 * u + 2 * t);
                    double r = base + wrinkle;
                    if (layer == 2) r -= 2.6 * gap * std::exp(-(d - dent).squaredNorm() / 0.004);
                    out[std::size_t{j} * n + i] = r * d;
                }
        };
        objects.push_back(object_of("layer_" + std::to_string(layer), grid_triangles(n, n), n * n, place));
    }
    return family_scene("contact-layers", preset, seed, std::move(objects), frames);
}

// ---- contact-spheres -------------------------------------------------------------------

Scene make_spheres(Preset preset, std::uint64_t seed) {
    const std::uint32_t across = pick(preset, 2, 3, 4), high = pick(preset, 1, 2, 3);
    const std::uint32_t segments = pick(preset, 16, 48, 80), rings = pick(preset, 8, 24, 40);
    const std::uint32_t frames = frames_of(preset);
    constexpr double radius = 0.25, gap = 0.002 * radius;
    Random random(seed, 0xD2);
    std::vector<Vec3> jitter;
    for (std::uint32_t k = 0; k < across * across * high; ++k) jitter.push_back(0.04 * radius * random.in_cube());
    // Centres at frame f: the lattice, compressed by up to 9% of a diameter.
    const auto centres = [=](std::uint32_t frame) {
        const double spacing = 2 * radius * (1 - 0.09 * frame_time(frame, frames));
        std::vector<Vec3> out;
        for (std::uint32_t z = 0; z < high; ++z)
            for (std::uint32_t y = 0; y < across; ++y)
                for (std::uint32_t x = 0; x < across; ++x)
                    out.push_back(spacing * Vec3(x + 0.5 * (z % 2), y + 0.5 * (z % 2), 0.8 * z) + jitter[out.size()]);
        return out;
    };
    std::vector<GeneratedObject> objects;
    for (std::uint32_t k = 0; k < across * across * high; ++k) {
        objects.push_back(sphere_object("sphere_" + std::to_string(k), segments, rings,
                                        [=](std::uint32_t frame, std::span<const Vec3> unit, std::span<Vec3> out) {
            const std::vector<Vec3> c = centres(frame);
            for (std::size_t v = 0; v < unit.size(); ++v) {
                Vec3 p = c[k] + radius * unit[v];
                // Flattened against each neighbour: onto the plane half a gap short of the mid-plane.
                for (int pass = 0; pass < 3; ++pass)
                    for (std::size_t j = 0; j < c.size(); ++j) {
                        const Vec3 between = c[j] - c[k];
                        const double distance = between.norm();
                        if (j == k || distance >= 2 * radius) continue;
                        const Vec3 normal = between / distance;
                        const double beyond = (p - c[k]).dot(normal) - (0.5 * distance - 0.5 * gap);
                        if (beyond > 0) p -= beyond * normal;
                    }
                out[v] = p;
            }
        }));
    }
    return family_scene("contact-spheres", preset, seed, std::move(objects), frames);
}

// ---- contact-rods ----------------------------------------------------------------------

Scene make_rods(Preset preset, std::uint64_t seed) {
    const std::uint32_t rods = pick(preset, 3, 5, 7), around = pick(preset, 12, 32, 48), along = pick(preset, 24, 300, 700);
    const std::uint32_t frames = frames_of(preset);
    constexpr double tube = 0.05, gap = 0.02 * tube, length = 3;
    const double helix = (2 * tube + gap) / (2 * std::sin(k_pi / rods));
    Random random(seed, 0xD3);
    const double twist_start = random.uniform(1.5, 2.5);  // turns over the length
    std::vector<GeneratedObject> objects;
    for (std::uint32_t rod = 0; rod < rods; ++rod) {
        auto place = [=](std::uint32_t frame, std::span<Vec3> out) {
            const double turns = twist_start * (1 + 0.6 * frame_time(frame, frames));
            for (std::uint32_t k = 0; k < along; ++k) {
                const double s = lerp_grid(k, along, 0, 1);
                const double angle = 2 * k_pi * (rod / double(rods) + turns * s);
                const Vec3 centre(helix * std::cos(angle), helix * std::sin(angle), length * s);
                for (std::uint32_t i = 0; i < around; ++i) {
                    const double a = 2 * k_pi * i / around;
                    out[std::size_t{k} * around + i] = centre + Vec3(tube * std::cos(a), tube * std::sin(a), 0);
                }
            }
        };
        objects.push_back(object_of("rod_" + std::to_string(rod), tube_triangles(around, along), around * along, place));
    }
    return family_scene("contact-rods", preset, seed, std::move(objects), frames);
}

// ---- contact-rollers -------------------------------------------------------------------

Scene make_rollers(Preset preset, std::uint64_t seed) {
    const std::uint32_t segments = pick(preset, 24, 160, 500), rings = pick(preset, 12, 80, 250);
    const std::uint32_t around = pick(preset, 16, 64, 160), along = pick(preset, 8, 64, 200);
    const std::uint32_t frames = frames_of(preset);
    constexpr double roller = 0.3, width = 1.2, gap = 0.002;
    const Vec3 body_radii(0.6, 0.35, 0.3);
    Random random(seed, 0xD4);
    const double spin = random.uniform(0.5, 1.0);
    // Roller r (0 below, 1 above) at frame f: its axis along y through (0, height).
    const auto axis_height = [frames](std::uint32_t roller_index, std::uint32_t frame) {
        const double press = 0.3 - 0.12 * frame_time(frame, frames);  // the rollers close in
        return (roller_index == 0 ? -1.0 : 1.0) * (press + roller);
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(sphere_object("body", segments, rings,
                                    [=](std::uint32_t frame, std::span<const Vec3> unit, std::span<Vec3> out) {
        const double shift = -0.4 + 0.8 * frame_time(frame, frames);  // drawn through along x
        for (std::size_t v = 0; v < unit.size(); ++v) {
            Vec3 p = body_radii.cwiseProduct(unit[v]) + Vec3(shift, 0, 0);
            for (std::uint32_t r = 0; r < 2; ++r) {
                const double dx = p.x(), dz = p.z() - axis_height(r, frame);
                const double distance = std::hypot(dx, dz);
                if (distance < roller + gap && distance > 0) {
                    const double scale = (roller + gap) / distance;
                    p = Vec3(dx * scale, p.y(), axis_height(r, frame) + dz * scale);
                }
            }
            out[v] = p;
        }
    }));
    for (std::uint32_t r = 0; r < 2; ++r) {
        auto place = [=](std::uint32_t frame, std::span<Vec3> out) {
            const double turned = (r == 0 ? 1 : -1) * spin * frame_time(frame, frames);
            for (std::uint32_t k = 0; k < along; ++k) {
                const double y = lerp_grid(k, along, -0.5 * width, 0.5 * width);
                for (std::uint32_t i = 0; i < around; ++i) {
                    const double a = 2 * k_pi * i / around + turned;
                    out[std::size_t{k} * around + i] =
                        Vec3(roller * std::cos(a), y, axis_height(r, frame) + roller * std::sin(a));
                }
            }
        };
        objects.push_back(object_of("roller_" + std::to_string(r), tube_triangles(around, along), around * along, place));
    }
    return family_scene("contact-rollers", preset, seed, std::move(objects), frames);
}

// ---- coplanar-stack --------------------------------------------------------------------

Scene make_stack(Preset preset, std::uint64_t seed) {
    const std::uint32_t n = pick(preset, 12, 100, 240);
    const std::uint32_t frames = frames_of(preset);
    constexpr double plane = 0.1;
    Random random(seed, 0xD5);
    std::vector<GeneratedObject> objects;
    for (std::uint32_t patch = 0; patch < 4; ++patch) {
        // Each patch starts a little off its quarter of a 2 x 2 layout that overlaps by half a
        // side, and drifts and turns in the plane.
        const double x0 = (patch % 2) * 0.5 + random.uniform(-0.05, 0.05);
        const double y0 = (patch / 2) * 0.5 + random.uniform(-0.05, 0.05);
        const double turn = random.uniform(-0.3, 0.3), drift = random.uniform(-0.15, 0.15);
        auto place = [=](std::uint32_t frame, std::span<Vec3> out) {
            const double t = frame_time(frame, frames);
            const double c = std::cos(turn * t), s = std::sin(turn * t);
            for (std::uint32_t j = 0; j < n; ++j)
                for (std::uint32_t i = 0; i < n; ++i) {
                    const double u = lerp_grid(i, n, -0.5, 0.5), v = lerp_grid(j, n, -0.5, 0.5);
                    out[std::size_t{j} * n + i] = Vec3(x0 + drift * t + c * u - s * v, y0 - drift * t + s * u + c * v, plane);
                }
        };
        objects.push_back(object_of("patch_" + std::to_string(patch), grid_triangles(n, n), n * n, place));
    }
    return family_scene("coplanar-stack", preset, seed, std::move(objects), frames);
}

}  // namespace

Scene make_contact_scene(std::string_view name, std::string_view preset_text, std::uint64_t seed) {
    const Preset preset = parse_preset(preset_text, name);
    if (name == "contact-layers") return make_layers(preset, seed);
    if (name == "contact-spheres") return make_spheres(preset, seed);
    if (name == "contact-rods") return make_rods(preset, seed);
    if (name == "contact-rollers") return make_rollers(preset, seed);
    if (name == "coplanar-stack") return make_stack(preset, seed);
    throw InputError("unknown contact scene '" + std::string(name) + "'");
}

}  // namespace collidescope::datasets
