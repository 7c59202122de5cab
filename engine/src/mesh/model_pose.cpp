// pose_instance: morph, then skin or place by the node's global transform.

#include "mesh/model_pose.hpp"

#include "mesh/morph.hpp"
#include "mesh/skinning.hpp"

#include "mesh/vertex_blocks.hpp"

namespace collidescope::animation {
namespace {

void place(std::span<const Vec3> positions, const Affine& transform, std::span<Vec3> out) {
    for_vertex_blocks(positions.size(), 8192,
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) out[v] = apply(transform, positions[v]);
    });
}

}  // namespace

void pose_instance(const MeshInstance& instance, const Pose& pose, PoseScratch& scratch,
                   std::vector<Vec3>& out) {
    out.resize(instance.base.size());
    std::span<const Vec3> positions = instance.base;
    const std::vector<double>& weights = pose.morph_weights[instance.node];
    if (!weights.empty() && !instance.morph_targets.empty()) {
        scratch.morphed.resize(instance.base.size());
        apply_morph(instance.base, instance.morph_targets, weights, scratch.morphed);
        positions = scratch.morphed;
    }
    const Affine& node = pose.global[instance.node];
    if (!instance.skinned()) {
        place(positions, node, out);
        return;
    }
    scratch.bone_matrices.resize(instance.bone_nodes.size());
    for (std::size_t b = 0; b < instance.bone_nodes.size(); ++b) {
        scratch.bone_matrices[b] = compose(pose.global[instance.bone_nodes[b]], instance.bone_offsets[b]);
    }
    const Influences influences{instance.influence_begin, instance.influence_bone, instance.influence_weight};
    skin(positions, influences, scratch.bone_matrices, node, out);
}

}  // namespace collidescope::animation
