#pragma once
// One mesh instance's vertices in scene space for a Pose (engine/src/mesh, private):
// morph targets first (in the mesh's space), then skinning (skinned meshes) or the instance
// node's global transform (unskinned meshes). docs/reference/animation.md.

#include "mesh/animation_clip.hpp"

#include <vector>

namespace collidescope::animation {

/// Reusable buffers for pose_instance (no allocation once warm).
struct PoseScratch {
    std::vector<Vec3> morphed;
    std::vector<Affine> bone_matrices;
};

/// Writes `instance`'s vertices posed by `pose` into `out` (resized to instance.base.size()).
void pose_instance(const MeshInstance& instance, const Pose& pose, PoseScratch& scratch,
                   std::vector<Vec3>& out);

}  // namespace collidescope::animation
