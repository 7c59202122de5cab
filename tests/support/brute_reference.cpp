// The all-pairs reference.

#include "support/brute_reference.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>
#include <ostream>

namespace collidescope::testing {

std::vector<TrianglePair> reference_colliding_pairs(const Frame& frame, bool self_collision) {
    std::vector<TrianglePair> pairs;
    const auto objects = static_cast<std::uint32_t>(frame.objects.size());
    for (std::uint32_t a = 0; a < objects; ++a) {
        const ObjectFrame& object_a = frame.objects[a];
        for (std::uint32_t b = a; b < objects; ++b) {
            if (a == b && !self_collision) continue;
            const ObjectFrame& object_b = frame.objects[b];
            for (std::uint32_t i = 0; i < object_a.triangle_count(); ++i) {
                // Within one object, each unordered pair once (j > i); between objects, all.
                for (std::uint32_t j = (a == b ? i + 1 : 0); j < object_b.triangle_count(); ++j) {
                    const std::array<Vec3, 3> pa = object_a.corners(i);
                    const std::array<Vec3, 3> pb = object_b.corners(j);
                    const bool hit = a == b ? self_triangles_collide(object_a.topology->triangles[i], pa,
                                                                     object_b.topology->triangles[j], pb)
                                            : triangles_intersect(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
                    if (hit) pairs.push_back({a, i, b, j});
                }
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace collidescope::testing

namespace collidescope {

void PrintTo(const TrianglePair& pair, std::ostream* out) {
    *out << "(" << pair.obj_a << "," << pair.tri_a << " | " << pair.obj_b << "," << pair.tri_b << ")";
}

}  // namespace collidescope
