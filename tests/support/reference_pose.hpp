#pragma once
// The slow, obvious evaluation of an animated model, straight from assimp's aiScene, that the
// engine's animation (mesh/animated_model, animation_clip, morph, skinning, model_pose) is
// checked against. Written independently: 4x4 matrices, its own key search and slerp, bones
// looked up by scanning every bone for every vertex, the node tree walked recursively.

#include "collidescope/types.hpp"

#include <assimp/scene.h>

#include <string>
#include <vector>

namespace collidescope::reference {

/// One mesh instance as the reference sees it: every vertex (unwelded, the file's indices)
/// posed, and its triangles as fans over those indices.
struct PosedInstance {
    std::string name;  ///< "<node>/<mesh>"
    std::vector<Vec3> vertices;
    std::vector<TriIndices> triangles;
};

/// Every mesh instance with at least one triangle, in depth-first node order, posed by clip
/// `clip` at `ticks`.
std::vector<PosedInstance> pose(const aiScene& scene, unsigned clip, double ticks);

}  // namespace collidescope::reference
