#pragma once
// The `brute` method (engine/src/methods): the brute-force culling (brute/brute_cull.hpp), then
// the shared exact narrow phase. The oracle every other method is tested against.

#include "collidescope/method.hpp"

#include <memory>

namespace collidescope {

/// Makes the `brute` method.
std::unique_ptr<Method> make_brute_method();

}  // namespace collidescope
