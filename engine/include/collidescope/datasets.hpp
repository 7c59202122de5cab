#pragma once
/// Built-in scenes (engine/src/datasets): generated in memory, deterministic, no files.
///
/// A scene is named `NAME[:PRESET]`; the preset picks a size. For now one scene, `demo`; the
/// thesis's data sets A-E join this registry in a later issue.

#include "collidescope/scene.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

/// Makes the built-in scene `spec` = `NAME[:PRESET]` (no preset: the scene's default preset).
/// Throws InputError naming the known scenes (or the scene's known presets) on an unknown one.
Scene make_builtin_scene(std::string_view spec);

/// The built-in scene names, in a stable order.
std::vector<std::string> builtin_scene_names();

/// The presets of built-in scene `name`, default first. Throws InputError on an unknown name.
std::vector<std::string> builtin_scene_presets(std::string_view name);

}  // namespace collidescope
