#pragma once
// Mode 2's final step (engine/src/gpucull, private; thesis 4.2, the rebuild cost R): each
// object's surviving triangles get a fresh hierarchy (the Mode 1 builder), and a traversal of
// the object pairs gives candidate pairs for the exact test. Self-collision pairs within one
// object skip the GPU (the cull is inter-object), so a self-colliding object's hierarchy holds
// all its triangles for its self-traversal, with surface patches when the object is a surface
// (Mode 1's self-collision culling, bvh/surface_patches.hpp).

#include "gpucull/image_space_cull.hpp"

#include "collidescope/frame_context.hpp"

#include <vector>

namespace collidescope::gpucull {

/// What the final step did.
struct FinalStepStats {
    std::uint64_t nodes_visited = 0;
    std::uint64_t box_tests = 0;
    std::uint64_t self_culled_triangles = 0;
    std::uint64_t adjacent_apart = 0;
};

/// Candidate pairs (canonical, triangle ids of the file) among the survivors `pcs` of every
/// inter-object pair of `context`, and within every object when self-collision is on.
std::vector<TrianglePair> final_step_candidates(const FrameContext& context, const std::vector<PcsObject>& pcs,
                                                FinalStepStats& stats);

}  // namespace collidescope::gpucull
