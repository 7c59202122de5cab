// The Embree + CGAL peer's narrow phase: DESIGN.md's "collide" with CGAL's filtered exact
// predicates. The self rule's case analysis (shared vertex, shared edge, degenerate
// triangles) follows DESIGN.md; each case is decided with CGAL predicates:
//
// Shared vertex v, T1 = (v, a, b), T2 = (v, c, d): T1 ∩ T2 is convex and holds v, so it holds
// another point iff the far end y of a segment [v, x] in it lies either on an edge opposite v
// (edge [a, b] meets T2 with v not on [a, b], or [c, d] meets T1 with v not on [c, d]) or on
// an edge through v, whose direction then lies in the other triangle's tangent cone at v.
// Shared edge [u, v], u != v, apexes a and b: two non-degenerate triangles meet beyond the
// edge iff they are coplanar with a and b strictly on one side of line uv (a fold-over); a
// degenerate one is a segment on line uv, which meets the other only in [u, v] unless both
// are degenerate and stick out past the same end.

#include "peers/cgal_narrow_phase.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <variant>

namespace collidescope::peers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
/// A closed triangle as the point set it is: a triangle, a segment or a point.
using Shape = std::variant<Point, Segment, Triangle>;

Point to_point(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Shape segment_shape(const Point& p, const Point& q) {
    if (p == q) return p;
    return Segment(p, q);
}

Shape triangle_shape(const Point& p, const Point& q, const Point& r) {
    if (!CGAL::collinear(p, q, r)) return Triangle(p, q, r);
    // Collinear: the segment between the two extreme corners (a point when all coincide).
    if (CGAL::collinear_are_ordered_along_line(q, p, r)) return segment_shape(q, r);
    if (CGAL::collinear_are_ordered_along_line(p, q, r)) return segment_shape(p, r);
    return segment_shape(p, q);
}

// do_intersect over the non-degenerate primitives CGAL accepts, both orders.
struct Intersects {
    bool operator()(const Point& p, const Point& q) const { return p == q; }
    bool operator()(const Point& p, const Segment& s) const { return s.has_on(p); }
    bool operator()(const Point& p, const Triangle& t) const { return CGAL::do_intersect(p, t); }
    bool operator()(const Segment& s, const Segment& t) const { return CGAL::do_intersect(s, t); }
    bool operator()(const Segment& s, const Triangle& t) const { return CGAL::do_intersect(s, t); }
    bool operator()(const Triangle& s, const Triangle& t) const { return CGAL::do_intersect(s, t); }
    template <class A, class B>
    bool operator()(const A& a, const B& b) const { return (*this)(b, a); }
};

bool intersects(const Shape& a, const Shape& b) { return std::visit(Intersects{}, a, b); }

/// v on the closed segment [a, b] (the point a when a == b).
bool on_segment(const Point& v, const Point& a, const Point& b) {
    if (a == b) return v == a;
    return CGAL::collinear(a, b, v) && CGAL::collinear_are_ordered_along_line(a, v, b);
}

/// q on the ray from v through c (c != v, q != v).
bool on_ray(const Point& v, const Point& c, const Point& q) {
    return CGAL::collinear(v, c, q) && !CGAL::collinear_are_strictly_ordered_along_line(q, v, c);
}

/// q != v and the direction q - v lies in the tangent cone at v of the closed triangle
/// (v, c, d): a short segment from v towards q lies in it.
bool direction_in_cone(const Point& v, const Point& q, const Point& c, const Point& d) {
    if (q == v) return false;
    if (CGAL::collinear(v, c, d)) {  // a segment through v, or a point: the rays towards c, d
        return (c != v && on_ray(v, c, q)) || (d != v && on_ray(v, d, q));
    }
    if (!CGAL::coplanar(v, c, d, q)) return false;
    // The cone (angle < pi) is the intersection of two closed half-planes of the plane.
    return CGAL::coplanar_orientation(v, c, d, q) != CGAL::NEGATIVE &&
           CGAL::coplanar_orientation(v, d, c, q) != CGAL::NEGATIVE;
}

bool shared_vertex_collide(const Point& v, const Point& a, const Point& b, const Point& c,
                           const Point& d) {
    if (!on_segment(v, a, b) && intersects(segment_shape(a, b), triangle_shape(v, c, d))) return true;
    if (!on_segment(v, c, d) && intersects(segment_shape(c, d), triangle_shape(v, a, b))) return true;
    return direction_in_cone(v, a, c, d) || direction_in_cone(v, b, c, d) ||
           direction_in_cone(v, c, a, b) || direction_in_cone(v, d, a, b);
}

bool shared_edge_collide(const Point& u, const Point& v, const Point& a, const Point& b) {
    const bool flat_a = CGAL::collinear(u, v, a), flat_b = CGAL::collinear(u, v, b);
    if (flat_a && flat_b) {
        const auto beyond_u = [&](const Point& x) { return CGAL::collinear_are_strictly_ordered_along_line(x, u, v); };
        const auto beyond_v = [&](const Point& x) { return CGAL::collinear_are_strictly_ordered_along_line(u, v, x); };
        return (beyond_u(a) && beyond_u(b)) || (beyond_v(a) && beyond_v(b));
    }
    if (flat_a || flat_b) return false;
    if (!CGAL::coplanar(u, v, a, b)) return false;
    return CGAL::coplanar_orientation(u, v, a, b) == CGAL::POSITIVE;
}

bool contains(const TriIndices& t, std::uint32_t index) { return std::find(t.begin(), t.end(), index) != t.end(); }

bool subset_of(const TriIndices& t, const TriIndices& of) {
    return contains(of, t[0]) && contains(of, t[1]) && contains(of, t[2]);
}

/// Corner k of `t` whose index is `index`.
int corner_of(const TriIndices& t, std::uint32_t index) { return t[0] == index ? 0 : (t[1] == index ? 1 : 2); }

bool self_collide(const TriIndices& ia, const std::array<Point, 3>& pa, const TriIndices& ib,
                  const std::array<Point, 3>& pb) {
    // One triangle spanned by shared vertices lies inside their hull.
    if (subset_of(ia, ib) || subset_of(ib, ia)) return false;
    std::array<std::uint32_t, 3> shared{};
    int count = 0;
    for (std::uint32_t index : ia)
        if (contains(ib, index) && std::find(shared.begin(), shared.begin() + count, index) == shared.begin() + count)
            shared[count++] = index;
    if (count == 0) return intersects(triangle_shape(pa[0], pa[1], pa[2]), triangle_shape(pb[0], pb[1], pb[2]));
    if (count == 2) {  // neither is a subset: three distinct indices each
        const Point& u = pa[corner_of(ia, shared[0])];
        const Point& v = pa[corner_of(ia, shared[1])];
        const Point& a = pa[3 - corner_of(ia, shared[0]) - corner_of(ia, shared[1])];
        const Point& b = pb[3 - corner_of(ib, shared[0]) - corner_of(ib, shared[1])];
        if (u != v) return shared_edge_collide(u, v, a, b);
        return shared_vertex_collide(u, u, a, u, b);  // the hull is the point u == v
    }
    const int ka = corner_of(ia, shared[0]), kb = corner_of(ib, shared[0]);
    return shared_vertex_collide(pa[ka], pa[(ka + 1) % 3], pa[(ka + 2) % 3], pb[(kb + 1) % 3], pb[(kb + 2) % 3]);
}

std::array<Point, 3> corners(const ObjectFrame& object, std::uint32_t tri) {
    const std::array<Vec3, 3> c = object.corners(tri);
    return {to_point(c[0]), to_point(c[1]), to_point(c[2])};
}

}  // namespace

bool cgal_pair_collides(const Frame& frame, const TrianglePair& pair) {
    const ObjectFrame& a = frame.objects[pair.obj_a];
    const ObjectFrame& b = frame.objects[pair.obj_b];
    const std::array<Point, 3> pa = corners(a, pair.tri_a);
    const std::array<Point, 3> pb = corners(b, pair.tri_b);
    if (pair.obj_a == pair.obj_b)
        return self_collide(a.topology->triangles[pair.tri_a], pa, b.topology->triangles[pair.tri_b], pb);
    return intersects(triangle_shape(pa[0], pa[1], pa[2]), triangle_shape(pb[0], pb[1], pb[2]));
}

PairSet cgal_narrow_phase(const Frame& frame, std::span<const TrianglePair> candidates) {
    // CGAL's Epick predicates are thread-safe (their interval filters set the rounding mode of
    // the calling thread only), so the candidates split over TBB's threads as the engine's
    // narrow phase does (stages/narrow_phase.cpp), each thread keeping what it found.
    tbb::enumerable_thread_specific<PairSet> found;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 512),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          PairSet& local = found.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i)
                              if (cgal_pair_collides(frame, candidates[i])) local.push_back(candidates[i]);
                      });
    PairSet colliding;
    for (const PairSet& local : found) colliding.insert(colliding.end(), local.begin(), local.end());
    return colliding;
}

}  // namespace collidescope::peers
