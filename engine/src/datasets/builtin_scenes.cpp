// The registry of built-in scenes. A new scene adds one entry to k_scenes.

#include "datasets/demo_scene.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"

namespace collidescope {
namespace {

struct SceneEntry {
    std::string_view name;
    std::vector<std::string> (*presets)();  ///< default first
    Scene (*make)(const std::string& preset);
};

Scene make_demo(const std::string& preset) { return make_demo_scene(demo_config(preset), preset); }

// In the order builtin_scene_names() lists them.
constexpr SceneEntry k_scenes[] = {
    {"demo", &demo_presets, &make_demo},
};

const SceneEntry& find_scene(std::string_view name) {
    for (const SceneEntry& entry : k_scenes) {
        if (entry.name == name) return entry;
    }
    std::string known;
    for (const SceneEntry& entry : k_scenes) known += (known.empty() ? "" : ", ") + std::string(entry.name);
    throw InputError("unknown built-in scene '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace

Scene make_builtin_scene(std::string_view spec) {
    const std::size_t colon = spec.find(':');
    const SceneEntry& entry = find_scene(spec.substr(0, colon));
    const std::vector<std::string> presets = entry.presets();
    const std::string preset = colon == std::string_view::npos ? presets.front()
                                                               : std::string(spec.substr(colon + 1));
    for (const std::string& known : presets) {
        if (known == preset) return entry.make(preset);
    }
    std::string known;
    for (const std::string& name : presets) known += (known.empty() ? "" : ", ") + name;
    throw InputError("built-in scene '" + std::string(entry.name) + "': unknown preset '" + preset +
                     "' (known: " + known + ")");
}

std::vector<std::string> builtin_scene_names() {
    std::vector<std::string> names;
    for (const SceneEntry& entry : k_scenes) names.emplace_back(entry.name);
    return names;
}

std::vector<std::string> builtin_scene_presets(std::string_view name) {
    return find_scene(name).presets();
}

}  // namespace collidescope
