#pragma once
// The update stage's object boxes and the object level's sweep and prune
// (engine/src/stages, private; DESIGN.md "The engine, per frame", steps 1 and 2).
//
// Boxes are closed: two boxes that only touch overlap, because touching triangles collide.

#include "collidescope/frame_context.hpp"
#include "collidescope/scene.hpp"

#include <Eigen/Geometry>

#include <span>
#include <vector>

namespace collidescope {

/// One closed box per object over all its vertices (a vertex no triangle uses only makes the
/// box larger, which costs culling, never a pair). An object without vertices gets an empty box.
std::vector<Eigen::AlignedBox3d> compute_object_boxes(const Frame& frame);

/// True when the closed boxes share a point (touching counts). Empty boxes overlap nothing.
bool boxes_overlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b);

/// Sweep and prune on the x axis: objects sorted by box minimum, each compared with the ones
/// whose x interval starts at or before its own x maximum, then the full box check. Returns
/// the overlapping pairs (a < b), plus (a, a) for every object when `self_collision`, sorted.
std::vector<ObjectPair> find_object_pairs(std::span<const Eigen::AlignedBox3d> boxes,
                                          bool self_collision);

}  // namespace collidescope
