// Data-set test helpers: scenes by name, frame hashes, all-pairs collision counts.

#include "scene_helpers.hpp"

#include "collidescope/error.hpp"
#include "collidescope/geometry.hpp"
#include "datasets/generators.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace collidescope::testing {
namespace {

struct TriangleBox {
    Vec3 lo, hi;
    std::uint32_t object = 0;
    std::uint32_t triangle = 0;
};

std::vector<TriangleBox> triangle_boxes(const Frame& frame) {
    std::vector<TriangleBox> boxes;
    for (std::uint32_t o = 0; o < frame.objects.size(); ++o) {
        const ObjectFrame& object = frame.objects[o];
        for (std::uint32_t t = 0; t < object.triangle_count(); ++t) {
            const std::array<Vec3, 3> c = object.corners(t);
            boxes.push_back({c[0].cwiseMin(c[1]).cwiseMin(c[2]),
                             c[0].cwiseMax(c[1]).cwiseMax(c[2]), o, t});
        }
    }
    std::sort(boxes.begin(), boxes.end(), [](const TriangleBox& a, const TriangleBox& b) {
        return a.lo.x() < b.lo.x();
    });
    return boxes;
}

bool boxes_overlap(const TriangleBox& a, const TriangleBox& b) {
    return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

bool pair_collides(const Frame& frame, const TriangleBox& a, const TriangleBox& b) {
    const ObjectFrame& oa = frame.objects[a.object];
    const ObjectFrame& ob = frame.objects[b.object];
    const std::array<Vec3, 3> pa = oa.corners(a.triangle);
    const std::array<Vec3, 3> pb = ob.corners(b.triangle);
    if (a.object != b.object) {
        return triangles_intersect(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
    }
    return self_triangles_collide(oa.topology->triangles[a.triangle], pa,
                                  ob.topology->triangles[b.triangle], pb);
}

std::uint64_t fnv(std::uint64_t hash, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001B3ULL;
    return hash;
}

}  // namespace

const std::vector<std::string>& dataset_names() {
    static const std::vector<std::string> names = {"A", "B", "C", "D", "E1", "E2", "E3", "E4"};
    return names;
}

void use_source_tree_data() {
#ifdef COLLIDESCOPE_SOURCE_DIR
    ::setenv("COLLIDESCOPE_DATA", COLLIDESCOPE_SOURCE_DIR "/data", 0);  // 0: keep a set value
#endif
}

std::optional<Scene> try_make_scene(std::string_view name, std::string_view preset,
                                    std::uint64_t seed, std::string& why) {
    use_source_tree_data();
    try {
        if (name == "A") return datasets::make_scene_A(preset, seed);
        if (name == "B") return datasets::make_scene_B(preset, seed);
        if (name == "C") return datasets::make_scene_C(preset, seed);
        if (name == "D") return datasets::make_scene_D(preset, seed);
        if (name.size() == 2 && name[0] == 'E') {
            return datasets::make_scene_E(name[1] - '0', preset, seed);
        }
    } catch (const UnavailableError& error) {
        why = error.what();
        return std::nullopt;
    }
    throw std::invalid_argument("no data set " + std::string(name));
}

std::uint64_t hash_frame(const Frame& frame, std::uint64_t hash) {
    for (const ObjectFrame& object : frame.objects) {
        const Topology& topology = *object.topology;
        hash = fnv(hash, &topology.vertex_count, sizeof topology.vertex_count);
        hash = fnv(hash, topology.triangles.data(), topology.triangles.size() * sizeof(TriIndices));
        for (const Vec3& v : object.vertices) hash = fnv(hash, v.data(), 3 * sizeof(double));
    }
    return hash;
}

CollisionCount count_collisions(const Frame& frame, bool self_collision) {
    const std::vector<TriangleBox> boxes = triangle_boxes(frame);
    CollisionCount count;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lo.x() <= boxes[i].hi.x(); ++j) {
            if (boxes[i].object == boxes[j].object && !self_collision) continue;
            if (!boxes_overlap(boxes[i], boxes[j])) continue;
            ++count.box_overlaps;
            if (pair_collides(frame, boxes[i], boxes[j])) ++count.colliding;
        }
    }
    return count;
}

std::uint64_t triangle_count(const Frame& frame) {
    std::uint64_t triangles = 0;
    for (const ObjectFrame& object : frame.objects) triangles += object.triangle_count();
    return triangles;
}

}  // namespace collidescope::testing
