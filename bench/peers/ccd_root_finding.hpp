#pragma once
// The CCD peer's narrow phase (bench/peers, issue 39 point 4): one triangle pair over an
// interval, every vertex moving linearly from t = 0 to t = 1, tested the way the CPU codes of
// the literature do it (Provot 1997; Bridson, Fedkiw and Anderson 2002): for each of the six
// vertex-face and nine edge-edge queries, the cubic in t that is zero when the query's four
// points are coplanar, its roots in [0, 1] found by splitting the interval at the cubic's
// critical points (monotone pieces) and a safeguarded Newton iteration on each piece that
// changes sign, and at each root, in time order, a proximity test: the features' distance at
// that time at most δ. Plus, first, the engine's exact static test at t = 0 (so pairs already
// touching there count, as in ours) and at t = 1 for pass-through.
//
// Floating point, not exact: a root the cubic's rounding hides (a near-double root, a nearly
// coplanar motion) is missed. Degenerate cases handled as such codes handle them:
//   - a leading coefficient that is negligible: the lower degree (quadratic, linear);
//   - a critical point where |f| is tiny (a touching, double root): tested as a candidate;
//   - a cubic that is zero throughout (coplanar motion): the candidate times are the roots of
//     the 2D orientation quadratics in the plane (when a vertex crosses an edge's line), and
//     both ends; edges collinear throughout get only the two ends.
// The self rule mirrors ours (engine/src/ccd/pair_motion.cpp): two triangles of one object
// with the same index set are never a pair; queries whose features share a vertex index are
// not run; the ends use the exact self rule (self_triangles_collide).

#include "collidescope/types.hpp"

#include <array>
#include <optional>

namespace collidescope::peers {

/// A point's positions at t = 0 and t = 1.
using CcdPath = std::array<Vec3, 2>;

/// The two triangles at both ends; ia, ib their vertex indices (used when `self`).
struct CcdMotion {
    std::array<CcdPath, 3> a, b;
    TriIndices ia{}, ib{};
    bool self = false;
};

struct CcdOutcome {
    bool contact = false;
    double toi = 1;              ///< the earliest accepted root (0: touching at t = 0)
    bool start_contact = false;  ///< touching at t = 0 (exact test)
    bool pass_through = false;   ///< a contact, apart at both ends (exact tests)
};

/// Vertex p against triangle (a, b, c): the earliest time in [0, t_max] among the candidate
/// roots at which p is within `delta` of the triangle, if any.
std::optional<double> root_vertex_face(const CcdPath& p, const CcdPath& a, const CcdPath& b, const CcdPath& c,
                                       double delta, double t_max);

/// Edge (p0, p1) against edge (q0, q1), likewise.
std::optional<double> root_edge_edge(const CcdPath& p0, const CcdPath& p1, const CcdPath& q0, const CcdPath& q1,
                                     double delta, double t_max);

/// Distance from p to the closed triangle (a, b, c) (Ericson 5.1.5; a degenerate triangle:
/// its edges). Also the comparison's diagnosis (bench_ccd_peers --compare).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Distance between the closed segments (p0, p1) and (q0, q1) (Ericson 5.1.9).
double segment_segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

/// The pair: the static test at t = 0, else the earliest root over its queries (each query
/// first through the box of its features' positions at both ends, as ours).
CcdOutcome root_finding_test_pair(const CcdMotion& motion, double delta);

}  // namespace collidescope::peers
