// Object boxes and the sweep and prune over them.

#include "stages/object_level.hpp"

#include <algorithm>

namespace collidescope {

std::vector<Eigen::AlignedBox3d> compute_object_boxes(const Frame& frame) {
    std::vector<Eigen::AlignedBox3d> boxes(frame.objects.size());
    for (std::size_t o = 0; o < frame.objects.size(); ++o) {
        boxes[o].setEmpty();
        for (const Vec3& vertex : frame.objects[o].vertices) boxes[o].extend(vertex);
    }
    return boxes;
}

bool boxes_overlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
    if (a.isEmpty() || b.isEmpty()) return false;
    for (int axis = 0; axis < 3; ++axis) {
        if (a.min()[axis] > b.max()[axis] || b.min()[axis] > a.max()[axis]) return false;
    }
    return true;
}

std::vector<ObjectPair> find_object_pairs(std::span<const Eigen::AlignedBox3d> boxes,
                                          bool self_collision) {
    std::vector<std::uint32_t> order;
    order.reserve(boxes.size());
    for (std::uint32_t o = 0; o < boxes.size(); ++o) {
        if (!boxes[o].isEmpty()) order.push_back(o);
    }
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return boxes[a].min().x() < boxes[b].min().x() ||
               (boxes[a].min().x() == boxes[b].min().x() && a < b);
    });

    std::vector<ObjectPair> pairs;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Eigen::AlignedBox3d& box = boxes[order[k]];
        // Later objects start at or after this one; once one starts strictly beyond this
        // one's end, all the rest do too. Equal ends and starts touch, and touching counts.
        for (std::size_t m = k + 1; m < order.size(); ++m) {
            if (boxes[order[m]].min().x() > box.max().x()) break;
            if (!boxes_overlap(box, boxes[order[m]])) continue;
            pairs.push_back({std::min(order[k], order[m]), std::max(order[k], order[m])});
        }
    }
    if (self_collision) {
        for (std::uint32_t o = 0; o < boxes.size(); ++o) pairs.push_back({o, o});
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace collidescope
