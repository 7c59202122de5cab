#pragma once
// Running a loop body over blocks of vertices (engine/src/mesh, private): in parallel through
// TBB when there are more vertices than one block, inline otherwise (a character's small
// meshes would spend longer dispatching tasks than posing).

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace collidescope::animation {

/// Calls body(tbb::blocked_range<std::size_t>) over [0, count) in blocks of about `grain`.
template <typename Body>
void for_vertex_blocks(std::size_t count, std::size_t grain, const Body& body) {
    if (count <= grain) {
        body(tbb::blocked_range<std::size_t>(0, count));
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain), body);
}

}  // namespace collidescope::animation
