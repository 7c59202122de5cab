#pragma once
// Distance from points to a triangle mesh's surface (engine/src/regions, private): an AABB
// hierarchy over the mesh (bvh::build_tree), searched nearest box first.

#include "bvh/bvh.hpp"

#include <span>

namespace collidescope::regions {

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class SurfaceDistance {
public:
    /// The spans must outlive this object.
    SurfaceDistance(std::span<const TriIndices> triangles, std::span<const Vec3> vertices);
    /// The distance from p to the nearest point of any triangle (infinity without triangles).
    double operator()(const Vec3& p) const;

private:
    std::span<const TriIndices> m_triangles;
    std::span<const Vec3> m_vertices;
    bvh::Tree m_tree;
};

}  // namespace collidescope::regions
