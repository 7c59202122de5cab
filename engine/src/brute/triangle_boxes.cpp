// Per-triangle boxes, in parallel over triangles.

#include "brute/triangle_boxes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace collidescope {

std::vector<TriangleBox> triangle_boxes(const ObjectFrame& object) {
    std::vector<TriangleBox> boxes(object.triangle_count());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, boxes.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
            const std::array<Vec3, 3> corners = object.corners(static_cast<std::uint32_t>(t));
            for (int axis = 0; axis < 3; ++axis) {
                boxes[t].lo[axis] = std::min({corners[0][axis], corners[1][axis], corners[2][axis]});
                boxes[t].hi[axis] = std::max({corners[0][axis], corners[1][axis], corners[2][axis]});
            }
        }
    });
    return boxes;
}

}  // namespace collidescope
