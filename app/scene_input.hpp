#pragma once
// What every subcommand that runs a scene shares: INPUT files or `--scene NAME[:PRESET]`, and
// the self-collision override.

#include "collidescope/scene.hpp"

#include <string>
#include <vector>

namespace collidescope::app {

/// Opens INPUT files (mesh files, frame patterns, scene.json manifests) or the built-in scene
/// `scene` (NAME[:PRESET]); exactly one of the two must be given. Throws InputError otherwise.
/// `animation` says how animated model files are sampled.
Scene open_scene(const std::vector<std::string>& inputs, const std::string& scene,
                 const AnimationOptions& animation = {});

/// Self-collision for a run: forced on by --self, off by --no-self, else the scene's setting.
bool resolve_self_collision(bool self, bool no_self, const Scene& scene);

/// "A, B, C, ..., demo": the built-in scene names, for --help texts.
std::string builtin_scene_list();

}  // namespace collidescope::app
