#pragma once
// One triangle pair over an interval (engine/src/ccd, private): touching at the start (the
// exact per-frame test), else the earliest contact of its vertex-face and edge-edge queries.

#include "ccd/inclusion.hpp"
#include "ccd/query_cache.hpp"

#include <array>

namespace collidescope::ccd {

/// The two triangles at both ends: a[i] is corner i's path; ia, ib the vertex indices (the
/// self rule when `self`, and the edges' order in their queries); objects and triangle indices
/// name the features to a QueryCache.
struct PairMotion {
    std::array<Path, 3> a, b;
    TriIndices ia{}, ib{};
    bool self = false;
    std::uint32_t object_a = 0, tri_a = 0, object_b = 0, tri_b = 0;
    /// Each object's triangles share vertices (not a soup): only then do its queries recur
    /// across pairs, and go through the cache.
    bool shares_a = false, shares_b = false;
};

/// What test_pair found.
struct PairOutcome {
    bool contact = false;
    double toi = 1;
    bool start_contact = false;  ///< touching at t = 0 (toi 0)
    bool end_contact = false;    ///< touching at t = 1 (computed only for a contact)
    bool resolved = true;
    std::uint32_t queries = 0;   ///< primitive queries asked (past their box test and filters)
    std::uint64_t boxes = 0;     ///< boxes of their solutions (a stored one's counted again)
};

/// The times when the two triangles' boxes may overlap: [lo, hi] within [0, 1], empty when
/// lo > hi. Each triangle's box at time t lies within the box whose bounds move linearly
/// between its boxes at both ends (a coordinate's minimum over the corners is at least the
/// interpolation of its minima at the ends), so outside the window some axis parts those
/// boxes, and the triangles with them: no contact. The gaps' roots are rounded outward, so the
/// window holds every time the exact boxes meet. Empty wherever one triangle lies below the
/// other along an axis at both ends (their swept boxes can still overlap: two triangles flying
/// side by side), and also where different axes part the pair at different times. test_pair's
/// first filter; it never parts a pair whose boxes meet at some time.
struct OverlapWindow {
    double lo = 0, hi = 1;
    bool empty() const { return lo > hi; }
};
OverlapWindow overlap_window(const PairMotion& motion);

/// Whether the pair touches during the interval, and from when. Of one object (`self`),
/// features that share a vertex index are not queried and the ends use the self rule. With
/// `cache`, a query whose features recur across pairs (shares_a, shares_b) is taken from
/// there when it was stored: its filter's verdict, and before the pair's first contact its
/// solution (a query asked after a contact is solved up to it, as without a cache). The
/// outcome and its counts are the same with or without a cache, whatever the cache holds.
PairOutcome test_pair(const PairMotion& motion, double tolerance, std::uint32_t max_boxes, QueryCache* cache = nullptr);

}  // namespace collidescope::ccd
