// weld_instance: an animated model's mesh instance welded on the key (rest position, morph
// target positions, normalised influences sorted by bone): docs/reference/animation.md, Welding.

#include "mesh/animated_model.hpp"
#include "mesh/weld.hpp"

namespace collidescope::animation {
namespace {

void apply_welding(const Welding& welding, MeshInstance& instance) {
    const auto keep = [&](std::vector<Vec3>& positions) {
        std::vector<Vec3> kept;
        kept.reserve(welding.kept.size());
        for (const std::uint32_t v : welding.kept) kept.push_back(positions[v]);
        positions = std::move(kept);
    };
    keep(instance.base);
    for (std::vector<Vec3>& target : instance.morph_targets) keep(target);
    for (TriIndices& triangle : instance.triangles) {
        for (std::uint32_t& corner : triangle) corner = welding.remap[corner];
    }
    if (!instance.skinned()) return;
    std::vector<std::uint32_t> begin{0}, bones;
    std::vector<double> weights;
    for (const std::uint32_t v : welding.kept) {
        for (std::uint32_t i = instance.influence_begin[v]; i < instance.influence_begin[v + 1]; ++i) {
            bones.push_back(instance.influence_bone[i]);
            weights.push_back(instance.influence_weight[i]);
        }
        begin.push_back(static_cast<std::uint32_t>(bones.size()));
    }
    instance.influence_begin = std::move(begin);
    instance.influence_bone = std::move(bones);
    instance.influence_weight = std::move(weights);
}

}  // namespace

void weld_instance(MeshInstance& instance) {
    WeldKeys keys;
    std::vector<double> key;
    for (std::size_t v = 0; v < instance.base.size(); ++v) {
        key.clear();
        const auto push = [&](const Vec3& p) { key.insert(key.end(), {p.x(), p.y(), p.z()}); };
        push(instance.base[v]);
        for (const std::vector<Vec3>& target : instance.morph_targets) push(target[v]);
        if (instance.skinned()) {
            for (std::uint32_t i = instance.influence_begin[v]; i < instance.influence_begin[v + 1]; ++i) {
                key.push_back(instance.influence_bone[i]);
                key.push_back(instance.influence_weight[i]);
            }
        }
        keys.add(key);
    }
    apply_welding(weld(keys), instance);
}

}  // namespace collidescope::animation
