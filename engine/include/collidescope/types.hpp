#pragma once
/// Basic value types shared by every engine module.
///
/// Coordinates are stored as double: every float32 read from a file converts to double
/// exactly, and float64 files keep their values, so the exact predicates decide on the
/// input coordinates themselves (DESIGN.md, "What collide means").

#include <Eigen/Core>

#include <array>
#include <compare>
#include <cstdint>

namespace collidescope {

/// A point or vector in 3D, exactly the coordinates read from the input.
using Vec3 = Eigen::Vector3d;

/// `x` rounded to the nearest float32 (ties to even; overflow to infinity), as a double, which
/// holds it exactly: the precision most mesh files store. Out of line on purpose: the one
/// place the round trip is written (engine/src/geometry/float32.cpp says why). Thread-safe.
double round_to_float32(double x);

/// Each coordinate rounded to the nearest float32 (round_to_float32).
Vec3 round_to_float32(const Vec3& point);

/// True when `x` is a float32 value, so a float32 file keeps it exactly.
bool is_float32(double x);

/// Vertex indices of one triangle, in file order, into its object's vertex array.
using TriIndices = std::array<std::uint32_t, 3>;

/// One colliding (or candidate) triangle pair between two objects or within one.
/// Invariant for reported pairs: (obj_a, tri_a) < (obj_b, tri_b) lexicographically.
struct TrianglePair {
    std::uint32_t obj_a = 0;
    std::uint32_t tri_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t tri_b = 0;

    friend auto operator<=>(const TrianglePair&, const TrianglePair&) = default;
};

/// Builds a pair in canonical order ((obj,tri) of the first <= the second).
inline TrianglePair make_pair_ordered(std::uint32_t obj_a, std::uint32_t tri_a,
                                      std::uint32_t obj_b, std::uint32_t tri_b) {
    if (obj_b < obj_a || (obj_b == obj_a && tri_b < tri_a)) return {obj_b, tri_b, obj_a, tri_a};
    return {obj_a, tri_a, obj_b, tri_b};
}

}  // namespace collidescope
