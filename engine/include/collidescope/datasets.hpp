#pragma once
/// Built-in scenes (engine/src/datasets): generated in memory, deterministic, no files.
///
/// A scene is named `NAME[:PRESET]`; the preset picks a size. The thesis's data sets (chapter 5)
/// are `A` (two bunnies), `B` (waving cloths), `C` (sine-wave sheets), `D` (BART-like soup that
/// assembles), `E1`-`E4` (exploding dragons, fastest to slowest), each with the presets
/// `default`, `small` and `large` (docs/reference/datasets.md has their sizes); `demo` is a small
/// torus-and-sheet scene. The cloth family (`cloth-rest`, `cloth-drape`, `cloth-crumple`,
/// `cloth-slide`, the same three presets, self-collision on) stresses self-contact and exactly
/// coplanar contact. Longer aliases (`bunnies`, `cloths`, `sine-sheets`, `bart`,
/// `dragon-fastest` .. `dragon-slowest`) name the same scenes.

#include "collidescope/scene.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

/// Makes the built-in scene `spec` = `NAME[:PRESET]` (no preset: the scene's default preset).
/// Throws InputError naming the known scenes (or the scene's known presets) on an unknown one.
Scene make_builtin_scene(std::string_view spec);

/// The built-in scene names (canonical, not aliases), in a stable order: A, B, C, D, E1-E4, demo,
/// cloth-rest, cloth-drape, cloth-crumple, cloth-slide.
std::vector<std::string> builtin_scene_names();

/// The presets of built-in scene `name`, default first. Throws InputError on an unknown name.
std::vector<std::string> builtin_scene_presets(std::string_view name);

}  // namespace collidescope
