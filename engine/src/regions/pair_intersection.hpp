#pragma once
// One colliding pair's intersection (engine/src/regions, private): the segment, point or
// coplanar polygon, with what each end of a segment lies on, so that segments chain into curves
// by what they cross rather than by rounded coordinates.

#include "collidescope/regions.hpp"

#include <array>
#include <cstdint>

namespace collidescope::regions {

/// A vertex, edge or face of one object: kind Vertex (a), Edge (a < b: vertex ids) or Face
/// (a: triangle id).
struct Feature {
    enum Kind : std::uint8_t { Vertex, Edge, Face };
    std::uint32_t object = 0;
    std::uint8_t kind = Vertex;
    std::uint32_t a = 0;
    std::uint32_t b = 0;

    friend bool operator==(const Feature&, const Feature&) = default;
    friend auto operator<=>(const Feature&, const Feature&) = default;
};

/// Where a segment's end lies: on a feature of each surface (an edge of one crossing the face of
/// the other, or, where the crossing falls exactly on an edge or vertex of that face, that edge
/// or vertex), the two in canonical order. Located with exact predicates, so every pair whose
/// segment ends there computes the same key: two segments of a curve meet at equal keys, also
/// where a curve passes exactly through an edge-edge crossing or a vertex. `valid` false: an
/// end of no feature (rounding put it between), which chains with nothing.
struct EndKey {
    Feature first;
    Feature second;
    bool valid = false;

    friend bool operator==(const EndKey&, const EndKey&) = default;
    friend auto operator<=>(const EndKey&, const EndKey&) = default;
};

/// A hash of a key (equal keys hash equal). Sorting keys by (hash, key) puts equal keys
/// together, as sorting by key does, with one integer comparison deciding nearly every step
/// instead of the features' fields one by one.
inline std::uint64_t key_hash(const EndKey& key) {
    std::uint64_t h = key.valid ? 0x9E3779B97F4A7C15ull : 0;
    for (const Feature& f : {key.first, key.second}) {
        for (const std::uint64_t x : {std::uint64_t(f.object) << 2 | f.kind, std::uint64_t(f.a) << 32 | f.b}) {
            h = (h ^ x) * 0xBF58476D1CE4E5B9ull;
            h ^= h >> 31;
        }
    }
    return h;
}

/// The compact form find_regions keeps per pair: a point, a segment with its ends' keys, or a
/// coplanar polygon by its area and box.
struct Piece {
    PairIntersection::Kind kind = PairIntersection::Kind::Point;
    /// The exact sides (orient3d's signs) of a's corners against b's plane, and of b's against
    /// a's, as the intersection decided them (all 0 for triangles in one axis-aligned plane):
    /// the penetration measure reads them instead of deciding them again. In the padding
    /// after `kind`: no larger.
    std::array<std::int8_t, 3> sides_a{}, sides_b{};
    std::array<Vec3, 2> ends;      ///< Point: ends[0]; Segment: both; Polygon: the box's min and max
    std::array<EndKey, 2> keys;    ///< Segment only
    double area = 0;               ///< Polygon only
};

/// orient3d(plane[0], plane[1], plane[2], t[i]) for each corner of t. `fast`: by one 2D
/// orientation and three comparisons where the plane's corners share a coordinate exactly.
std::array<int, 3> plane_sides(const std::array<Vec3, 3>& plane, const std::array<Vec3, 3>& t, bool fast = true);

/// The intersection of `pair`'s triangles in `frame`; `polygon` receives a coplanar
/// polygon's corners (or a point or segment's points) when not null. `fast` false: the general
/// path for every pair (no 2D clip for triangles in one axis-aligned plane, no four-orientation
/// crossing), and plane_sides without its shortcut (the tests compare the two).
Piece intersect(const Frame& frame, const TrianglePair& pair, std::vector<Vec3>* polygon = nullptr, bool fast = true);

}  // namespace collidescope::regions
