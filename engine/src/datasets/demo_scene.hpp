#pragma once
// The `demo` scene (engine/src/datasets, private): a waving sheet sweeps through a spinning
// torus, so the first and last frames are apart and the middle frames interpenetrate.

#include "collidescope/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace collidescope {

/// Sizes of the demo scene.
struct DemoConfig {
    std::uint32_t frames = 60;         ///< animation length
    std::uint32_t torus_major = 48;    ///< torus segments around the ring
    std::uint32_t torus_minor = 24;    ///< torus segments around the tube
    std::uint32_t sheet_cells = 32;    ///< sheet quads per side (two triangles each)
};

/// The demo presets, default first: "default" (4,352 triangles, 60 frames) and "small"
/// (456 triangles, 24 frames, for tests).
std::vector<std::string> demo_presets();

/// The DemoConfig of a preset from demo_presets(). Throws InputError on another name.
DemoConfig demo_config(const std::string& preset);

/// Generates the demo scene (object 0 "torus", object 1 "sheet"; self-collision off).
Scene make_demo_scene(const DemoConfig& config, const std::string& preset);

}  // namespace collidescope
