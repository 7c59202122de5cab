#pragma once
// The reference queries (engine/src/ccd, private): the same two questions as inclusion.hpp,
// answered the slow, obvious way. Interval arithmetic in which every operation's result is
// widened by at least one ulp on each side (a correctly rounded result is within half an ulp of the
// exact one, so the widened interval holds it), evaluated on the formula as written over a
// box of (t, u, v); a box whose interval for some coordinate excludes 0 holds no contact.
// Boxes are halved in all three parameters at once, earliest first; one is accepted when each
// coordinate's interval lies within δ of 0 and its earliest corner is in the domain.

#include "ccd/inclusion.hpp"

namespace collidescope::ccd::reference {

/// What is searched: the times from `first` to config.t_max (the tests ask about one
/// instant), for a point where every coordinate of F is within `margin` of 0 (0: a contact).
struct Times {
    double first = 0;
    double margin = 0;
};

/// As ccd::vertex_face: p against the triangle (a, b, c).
QueryResult vertex_face(const Path& p, const Path& a, const Path& b, const Path& c, const QueryConfig& config,
                        Times times = {});

/// As ccd::edge_edge: (p0, p1) against (q0, q1).
QueryResult edge_edge(const Path& p0, const Path& p1, const Path& q0, const Path& q1, const QueryConfig& config,
                      Times times = {});

}  // namespace collidescope::ccd::reference
