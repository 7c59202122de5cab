#pragma once
// The brute-force method (engine/src/brute): the oracle every other method is tested against.
//
// Owns nothing but the obvious algorithm: for each object pair the object level hands it,
// every triangle pair (every i < j within one object under self-collision), a closed
// per-triangle box prefilter, then the exact test (pipeline/narrow_phase). It must stay
// obviously correct; speed is the other methods' business. It keeps no state between frames.

#include "collidescope/pipeline.hpp"

#include <memory>

namespace collidescope {

/// Makes the `brute` method.
std::unique_ptr<Method> make_brute_method();

}  // namespace collidescope
