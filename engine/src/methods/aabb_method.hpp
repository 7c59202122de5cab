#pragma once
// The `aabb` method (Mode 1, thesis 4.4.1; engine/src/methods): the AABB culling
// (bvh/aabb_culler.hpp), then the shared exact narrow phase.

#include "bvh/aabb_culler.hpp"

#include "collidescope/method.hpp"

#include <memory>

namespace collidescope {

/// Makes the `aabb` method with its own trees, configured by `config` (the default: LBVH, the
/// quality rebuild rule, rebuilds on a worker).
std::unique_ptr<Method> make_aabb_method(bvh::AabbConfig config = {});

/// Makes the `aabb` method over `culler`, whose trees it shares with other methods (the
/// `adaptive` method's AABB runs: the trees stay warm whichever method serves a frame).
std::unique_ptr<Method> make_aabb_method(std::shared_ptr<bvh::AabbCuller> culler);

}  // namespace collidescope
