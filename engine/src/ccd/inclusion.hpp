#pragma once
// The primitive queries of continuous detection (engine/src/ccd, private): a vertex against a
// face and an edge against an edge, each vertex moving linearly from its position at t = 0 to
// its position at t = 1. Both are written as one function of (t, u, v) in [0, 1]^3,
//   F(t, u, v) = X(t) + u Y(t) + v Z(t),   X, Y, Z linear in t,
// whose zero is a contact: vertex-face F = p - (a + u (b - a) + v (c - a)) with u + v <= 1;
// edge-edge F = p0 + u (p1 - p0) - (q0 + v (q1 - q0)). F is multilinear (degree at most one in
// each of t, u, v), so over a box of (t, u, v) each coordinate of F lies between the least and
// the greatest of its values at the box's eight corners: an inclusion that is exact up to the
// rounding of those eight evaluations, which a static bound covers (inclusion.cpp).

#include "collidescope/types.hpp"

#include <array>
#include <cstdint>

namespace collidescope::ccd {

/// A point's two positions: at t = 0 and at t = 1.
using Path = std::array<Vec3, 2>;

/// What a query asks.
struct QueryConfig {
    double tolerance = 1e-6;          ///< δ: accept a box whose values lie within δ of 0
    double t_max = 1;                 ///< times after this are of no interest (an earlier contact is known)
    std::uint32_t max_boxes = 50000;   ///< then stop: conservatively a contact
};

/// What a query found.
struct QueryResult {
    bool hit = false;
    /// With hit: a lower bound of the earliest contact in [0, t_max]; at this time the
    /// features are within the tolerance of each other (unless !resolved).
    double toi = 1;
    bool resolved = true;        ///< false: max_boxes reached (toi is still a lower bound)
    std::uint32_t boxes = 0;     ///< boxes evaluated
};

/// The moving plane of a triangle (a, b, c), to tell which side of it moving points stay on.
class MovingPlane {
public:
    /// `largest`: at least the magnitude of every coordinate of the triangle's paths and of
    /// every point's that side() is asked about.
    MovingPlane(const Path& a, const Path& b, const Path& c, double largest);

    /// 1 or -1 when the signed volume det(p - a, b - a, c - a) is certainly of that sign at
    /// every time of the interval (decided from the Bernstein coefficients of that cubic,
    /// beyond their rounding bound), 0 when it may vanish. The end coefficients first: the
    /// inner two, and the cross products they need, only for a point certainly on one side at
    /// both ends (most points that reach a plane cross it).
    int side(const Path& p);

private:
    Path m_origin;
    Path m_y, m_z;                  ///< b - a and c - a at both ends
    std::array<Vec3, 4> m_crosses;  ///< y[j] x z[k] at 2j + k; the mixed ones (1, 2) made once needed
    bool m_mixed = false;
    double m_error;
};

/// Vertex p against the triangle (a, b, c).
QueryResult vertex_face(const Path& p, const Path& a, const Path& b, const Path& c, const QueryConfig& config);

/// Vertex p against the triangle (a, b, c) when all eight positions (each point's at t = 0 and
/// at t = 1) lie exactly in one plane whose normal has a non-zero component along axis `drop`:
/// the same answer as vertex_face, found by halving the times on the three edge orientations
/// of the projection that drops that axis (quadratics in t) before the boxes search the few
/// spans they leave. On positions not in one plane it may miss contacts.
QueryResult vertex_face_in_plane(const Path& p, const Path& a, const Path& b, const Path& c, int drop,
                                 const QueryConfig& config);

/// Edge (p0, p1) against edge (q0, q1).
QueryResult edge_edge(const Path& p0, const Path& p1, const Path& q0, const Path& q1, const QueryConfig& config);

}  // namespace collidescope::ccd
