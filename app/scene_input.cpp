// INPUT files or a built-in scene, shared by the subcommands that run a scene.

#include "scene_input.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"

namespace collidescope::app {

Scene open_scene(const std::vector<std::string>& inputs, const std::string& scene,
                 const AnimationOptions& animation) {
    if (!scene.empty() && !inputs.empty()) {
        throw InputError("give either INPUT files or --scene, not both");
    }
    if (!scene.empty()) return make_builtin_scene(scene);
    if (inputs.empty()) {
        throw InputError("no input: give INPUT files (mesh, frame pattern or scene.json) or --scene NAME");
    }
    return open_inputs(inputs, animation);
}

bool resolve_self_collision(bool self, bool no_self, const Scene& scene) {
    if (self) return true;
    if (no_self) return false;
    return scene.self_collision;
}

std::string builtin_scene_list() {
    std::string names;
    for (const std::string& name : builtin_scene_names()) names += (names.empty() ? "" : ", ") + name;
    return names;
}

}  // namespace collidescope::app
