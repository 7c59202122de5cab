// The registry of built-in scenes. A new scene adds one entry to k_scenes.

#include "datasets/demo_scene.hpp"
#include "datasets/generators.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"

namespace collidescope {
namespace {

struct SceneEntry {
    std::string_view name;
    std::vector<std::string> (*presets)();  ///< default first
    Scene (*make)(const std::string& preset);
};

// Every data set is generated from this seed unless a caller asks for another one (the
// generators take it as a parameter; the names give the documented animation).
constexpr std::uint64_t k_dataset_seed = 1;

Scene make_demo(const std::string& preset) { return make_demo_scene(demo_config(preset), preset); }

std::vector<std::string> dataset_presets() { return {"default", "small", "large"}; }

Scene make_A(const std::string& preset) { return datasets::make_scene_A(preset, k_dataset_seed); }
Scene make_B(const std::string& preset) { return datasets::make_scene_B(preset, k_dataset_seed); }
Scene make_C(const std::string& preset) { return datasets::make_scene_C(preset, k_dataset_seed); }
Scene make_D(const std::string& preset) { return datasets::make_scene_D(preset, k_dataset_seed); }
template <int speed>
Scene make_E(const std::string& preset) { return datasets::make_scene_E(speed, preset, k_dataset_seed); }
template <const char* name>
Scene make_cloth(const std::string& preset) { return datasets::make_cloth_scene(name, preset, k_dataset_seed); }
constexpr char k_cloth_rest[] = "cloth-rest";
constexpr char k_cloth_drape[] = "cloth-drape";
constexpr char k_cloth_crumple[] = "cloth-crumple";
constexpr char k_cloth_slide[] = "cloth-slide";
template <const char* name>
Scene make_contact(const std::string& preset) { return datasets::make_contact_scene(name, preset, k_dataset_seed); }
constexpr char k_contact_layers[] = "contact-layers";
constexpr char k_contact_spheres[] = "contact-spheres";
constexpr char k_contact_rods[] = "contact-rods";
constexpr char k_contact_rollers[] = "contact-rollers";
constexpr char k_coplanar_stack[] = "coplanar-stack";

// In the order builtin_scene_names() lists them: the thesis's data sets (chapter 5), the
// demo, the cloth family (issue 23), then the contact family (issue 37). Aliases are listed by builtin_scene_names() too, after the canonical names.
constexpr SceneEntry k_scenes[] = {
    {"A", &dataset_presets, &make_A},
    {"B", &dataset_presets, &make_B},
    {"C", &dataset_presets, &make_C},
    {"D", &dataset_presets, &make_D},
    {"E1", &dataset_presets, &make_E<1>},
    {"E2", &dataset_presets, &make_E<2>},
    {"E3", &dataset_presets, &make_E<3>},
    {"E4", &dataset_presets, &make_E<4>},
    {"demo", &demo_presets, &make_demo},
    {k_cloth_rest, &dataset_presets, &make_cloth<k_cloth_rest>},
    {k_cloth_drape, &dataset_presets, &make_cloth<k_cloth_drape>},
    {k_cloth_crumple, &dataset_presets, &make_cloth<k_cloth_crumple>},
    {k_cloth_slide, &dataset_presets, &make_cloth<k_cloth_slide>},
    {k_contact_layers, &dataset_presets, &make_contact<k_contact_layers>},
    {k_contact_spheres, &dataset_presets, &make_contact<k_contact_spheres>},
    {k_contact_rods, &dataset_presets, &make_contact<k_contact_rods>},
    {k_contact_rollers, &dataset_presets, &make_contact<k_contact_rollers>},
    {k_coplanar_stack, &dataset_presets, &make_contact<k_coplanar_stack>},
};

// Longer names for the data sets, resolved to the canonical ones.
struct SceneAlias {
    std::string_view alias;
    std::string_view name;
};
constexpr SceneAlias k_aliases[] = {
    {"bunnies", "A"}, {"cloths", "B"}, {"sine-sheets", "C"}, {"bart", "D"},
    {"dragon-fastest", "E1"}, {"dragon-fast", "E2"}, {"dragon-slow", "E3"}, {"dragon-slowest", "E4"},
};

std::string_view resolve_alias(std::string_view name) {
    for (const SceneAlias& alias : k_aliases) {
        if (alias.alias == name) return alias.name;
    }
    return name;
}

const SceneEntry& find_scene(std::string_view name) {
    name = resolve_alias(name);
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
