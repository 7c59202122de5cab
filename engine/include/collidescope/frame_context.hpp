#pragma once
/// What a frame's culling sees after the update and object level stages (engine/src/stages):
/// the frame, one box per object and the object pairs whose boxes overlap. The algorithms
/// (bvh, gpucull, hybrid, brute) take it as input; the methods hand it on.

#include "collidescope/scene.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <span>

namespace collidescope {

/// One object pair whose boxes overlap (a == b for self-collision).
struct ObjectPair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;

    friend auto operator<=>(const ObjectPair&, const ObjectPair&) = default;
};

/// What a method sees of the frame: the geometry and the update and object level results.
struct FrameContext {
    const Frame& frame;
    /// One closed box per object (over all its vertices), indexed like frame.objects.
    std::span<const Eigen::AlignedBox3d> object_boxes;
    /// Object pairs whose boxes overlap (closed: touching counts), sorted, a < b; plus (a, a)
    /// for every object when self_collision is on.
    std::span<const ObjectPair> object_pairs;
    bool self_collision = false;
};

}  // namespace collidescope
