// Sweep and prune over closed triangle boxes, along x.

#include "gpucull/survivor_pairs.hpp"

#include <algorithm>
#include <array>

namespace collidescope::gpucull {
namespace {

struct Box {
    std::array<double, 3> lo, hi;
    std::uint32_t tri;
    std::uint8_t side;  ///< 0: first set, 1: second set
};

Box box_of(const ObjectFrame& object, std::uint32_t tri, std::uint8_t side) {
    const std::array<Vec3, 3> p = object.corners(tri);
    Box box{{}, {}, tri, side};
    for (int axis = 0; axis < 3; ++axis) {
        box.lo[axis] = std::min({p[0][axis], p[1][axis], p[2][axis]});
        box.hi[axis] = std::max({p[0][axis], p[1][axis], p[2][axis]});
    }
    return box;
}

bool overlap_yz(const Box& p, const Box& q) {
    return p.lo[1] <= q.hi[1] && q.lo[1] <= p.hi[1] && p.lo[2] <= q.hi[2] && q.lo[2] <= p.hi[2];
}

// Calls visit(p, q) for every pair of boxes whose closed x intervals overlap; p precedes q in
// the sweep order. Returns the pairs examined.
template <class Visit>
std::uint64_t sweep(std::vector<Box>& boxes, Visit&& visit) {
    std::sort(boxes.begin(), boxes.end(), [](const Box& p, const Box& q) {
        return p.lo[0] < q.lo[0] || (p.lo[0] == q.lo[0] && (p.side < q.side || (p.side == q.side && p.tri < q.tri)));
    });
    std::uint64_t tests = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lo[0] <= boxes[i].hi[0]; ++j) {
            ++tests;
            visit(boxes[i], boxes[j]);
        }
    }
    return tests;
}

}  // namespace

std::uint64_t survivor_pairs(const Frame& frame, std::uint32_t a, std::span<const std::uint32_t> tris_a,
                             std::uint32_t b, std::span<const std::uint32_t> tris_b,
                             std::vector<TrianglePair>& candidates) {
    std::vector<Box> boxes;
    boxes.reserve(tris_a.size() + tris_b.size());
    for (const std::uint32_t tri : tris_a) boxes.push_back(box_of(frame.objects[a], tri, 0));
    for (const std::uint32_t tri : tris_b) boxes.push_back(box_of(frame.objects[b], tri, 1));
    return sweep(boxes, [&](const Box& p, const Box& q) {
        if (p.side == q.side || !overlap_yz(p, q)) return;
        const Box& first = p.side == 0 ? p : q;
        const Box& second = p.side == 0 ? q : p;
        candidates.push_back(make_pair_ordered(a, first.tri, b, second.tri));
    });
}

std::uint64_t self_pairs(const Frame& frame, std::uint32_t a, std::vector<TrianglePair>& candidates) {
    const ObjectFrame& object = frame.objects[a];
    std::vector<Box> boxes;
    boxes.reserve(object.triangle_count());
    for (std::uint32_t tri = 0; tri < object.triangle_count(); ++tri) boxes.push_back(box_of(object, tri, 0));
    return sweep(boxes, [&](const Box& p, const Box& q) {
        if (overlap_yz(p, q)) candidates.push_back(make_pair_ordered(a, p.tri, a, q.tri));
    });
}

}  // namespace collidescope::gpucull
