#pragma once
// An animated model as read through assimp (engine/src/mesh, private): the node tree, one
// entry per mesh instance (node and mesh) with its welded vertices, triangles, bone influences
// and morph targets, and the clips. Plain data in double precision; the evaluation lives in
// animation_clip (node channels), morph, skinning and model_pose. docs/reference/animation.md.

#include "collidescope/types.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::animation {

/// An affine transform for column vectors (assimp's matrices, transposed into Eigen's layout).
using Affine = Eigen::Matrix<double, 3, 4>;

/// Applies `m` to point `p`.
inline Vec3 apply(const Affine& m, const Vec3& p) {
    return m.leftCols<3>() * p + m.col(3);
}

/// `a * b` as 4x4 matrices with last row (0 0 0 1).
inline Affine compose(const Affine& a, const Affine& b) {
    Affine result;
    result.leftCols<3>() = a.leftCols<3>() * b.leftCols<3>();
    result.col(3) = a.leftCols<3>() * b.col(3) + a.col(3);
    return result;
}

/// One node of the tree, in depth-first (pre-)order: a parent comes before its children.
struct Node {
    std::string name;
    std::int32_t parent = -1;  ///< index into nodes, -1 for the root
    Affine local = Affine::Identity();  ///< rest transform relative to the parent
};

/// One mesh instance: an assimp mesh as referenced by one node, welded (weld.hpp).
struct MeshInstance {
    std::string name;         ///< "<node>/<mesh>"
    std::uint32_t node = 0;   ///< the node that references the mesh
    std::uint32_t mesh = 0;   ///< the aiScene mesh index
    std::vector<Vec3> base;   ///< rest positions in the mesh's space, welded
    std::vector<TriIndices> triangles;  ///< faces as fans, in file order, welded indices
    /// Skinning: bone b moves vertices by nodes[bone_nodes[b]]'s global transform times
    /// bone_offsets[b]. Empty for an unskinned mesh.
    std::vector<std::uint32_t> bone_nodes;
    std::vector<Affine> bone_offsets;
    /// Influences of vertex v: [influence_begin[v], influence_begin[v + 1]) into
    /// influence_bone / influence_weight, sorted by bone, weights normalised to sum 1. A vertex
    /// of a skinned mesh without influences follows its node (as an unskinned mesh does).
    std::vector<std::uint32_t> influence_begin;
    std::vector<std::uint32_t> influence_bone;
    std::vector<double> influence_weight;
    /// Morph targets (aiAnimMesh): absolute positions, welded like base.
    std::vector<std::vector<Vec3>> morph_targets;

    bool skinned() const { return !bone_nodes.empty(); }
};

/// A key of a vector channel (position, scaling), time in ticks.
struct VectorKey {
    double time = 0;
    Vec3 value = Vec3::Zero();
};

/// A key of a rotation channel, time in ticks.
struct RotationKey {
    double time = 0;
    Eigen::Quaterniond value = Eigen::Quaterniond::Identity();
};

/// A node's channel: never empty (a missing kind holds the node's rest component).
struct NodeChannel {
    std::uint32_t node = 0;
    std::vector<VectorKey> position;
    std::vector<RotationKey> rotation;
    std::vector<VectorKey> scaling;
};

/// A morph key: target weights at a time in ticks (targets not named weigh 0).
struct MorphKey {
    double time = 0;
    std::vector<double> weights;  ///< per morph target index
};

/// The morph weights of one node's meshes over time (aiMeshMorphAnim).
struct MorphChannel {
    std::uint32_t node = 0;
    std::vector<MorphKey> keys;
};

/// One animation clip.
struct Clip {
    std::string name;
    double duration_ticks = 0;
    double ticks_per_second = 25;  ///< assimp's 0 ("not given") reads as 25
    std::vector<NodeChannel> channels;
    std::vector<MorphChannel> morphs;

    double duration_seconds() const { return duration_ticks / ticks_per_second; }
};

/// Everything needed to pose the model at any time of any clip.
struct AnimatedModel {
    std::vector<Node> nodes;
    std::vector<MeshInstance> instances;  ///< depth-first node order, then the node's mesh order
    std::vector<Clip> clips;
    char up_axis = 0;  ///< 'x', 'y' or 'z' when the file says; 0 otherwise
};

/// Welds `instance` in place (weld.hpp): vertices with equal rest positions, morph target
/// positions and influences become the first of them; triangles are renumbered, not reordered.
void weld_instance(MeshInstance& instance);

/// Reads `file` through assimp (no post-processing) into an AnimatedModel: mesh instances with
/// at least one triangle, welded; clips with keys converted to double. Throws InputError naming
/// the file and the element: unreadable file, a bone naming no node, NaN or infinite keys,
/// weights or offsets, a mesh whose bone weights are all zero, a morph weight naming a target
/// the mesh lacks. With `only_if_animated`, a file without animations gives a model with only
/// `up_axis` filled (no nodes, instances or clips) and is not checked further: it is a static
/// mesh, read_with_assimp's business.
AnimatedModel read_animated_model(const std::filesystem::path& file, bool only_if_animated = false);

}  // namespace collidescope::animation
