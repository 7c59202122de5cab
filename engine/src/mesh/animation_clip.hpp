#pragma once
// Sampling a clip (engine/src/mesh, private): node channels and morph weights at one time.
//
// Between two keys, positions and scalings interpolate linearly, rotations by spherical
// linear interpolation on the shorter arc (then normalised), morph weights linearly; before
// the first key a channel holds the first key's value, after the last the last's. Nodes
// without a channel keep their rest transform. A node's local transform is T * R * S.

#include "mesh/animated_model.hpp"

#include <span>
#include <vector>

namespace collidescope::animation {

/// The model posed at one time: every node's global transform (root's included) and, per node,
/// the morph weights of its meshes (empty when the clip has no morph channel for the node).
/// Reused between frames: sampling assigns in place, without allocating once warm.
struct Pose {
    std::vector<Affine> global;
    std::vector<std::vector<double>> morph_weights;
};

/// A vector channel at time `ticks` (keys non-empty, in time order).
Vec3 sample_vector(std::span<const VectorKey> keys, double ticks);

/// A rotation channel at time `ticks` (keys non-empty, in time order), unit length.
Eigen::Quaterniond sample_rotation(std::span<const RotationKey> keys, double ticks);

/// Morph weights at time `ticks` into `weights` (resized to the widest key; keys non-empty).
void sample_morph(std::span<const MorphKey> keys, double ticks, std::vector<double>& weights);

/// T * R * S as an affine transform.
Affine trs(const Vec3& translation, const Eigen::Quaterniond& rotation, const Vec3& scaling);

/// Poses `model` by `clip` at `ticks` (clip time in ticks) into `pose`.
void sample_clip(const AnimatedModel& model, const Clip& clip, double ticks, Pose& pose);

/// `model` at rest (every node's own transform), no morph weights.
void rest_pose(const AnimatedModel& model, Pose& pose);

}  // namespace collidescope::animation
