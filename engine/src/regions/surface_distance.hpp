#pragma once
// Distance from points to a triangle mesh's surface (engine/src/regions, private): an AABB
// hierarchy over the mesh, searched nearest box first. The hierarchy of a topology is kept
// between calls and refit to the frame's vertices (a deforming mesh keeps its topology).

#include "bvh/bvh.hpp"

#include "collidescope/scene.hpp"

#include <limits>
#include <memory>
#include <span>

namespace collidescope::regions {

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class SurfaceDistance {
public:
    /// The surface of `topology` at `vertices`; both must outlive this object.
    SurfaceDistance(const Topology& topology, std::span<const Vec3> vertices);
    ~SurfaceDistance();
    SurfaceDistance(const SurfaceDistance&) = delete;
    SurfaceDistance& operator=(const SurfaceDistance&) = delete;
    /// The distance from p to the nearest point of any triangle (infinity without triangles).
    double operator()(const Vec3& p) const { return beyond(p, -1); }
    /// The distance from p to the surface when it exceeds `bound`; otherwise some value at most
    /// `bound` (the search stops at the first triangle within it). For the largest distance of
    /// many points, pass the largest so far: most searches then end early. `nearest_face`, when
    /// not null, receives the triangle at the distance returned (unchanged without triangles).
    /// `known`: the distance from p to some triangle (infinity: none known), which the search
    /// starts from, skipping every node farther than it; when nothing nearer is found, `known`
    /// is returned and `nearest_face` left unchanged (set it to that triangle beforehand).
    double beyond(const Vec3& p, double bound, std::uint32_t* nearest_face = nullptr,
                  double known = std::numeric_limits<double>::infinity()) const;

private:
    std::uint64_t m_revision;
    std::span<const TriIndices> m_triangles;
    std::span<const Vec3> m_vertices;
    std::unique_ptr<bvh::Tree> m_tree;  ///< taken from the cache, given back by the destructor
};

}  // namespace collidescope::regions
