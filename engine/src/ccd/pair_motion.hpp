#pragma once
// One triangle pair over an interval (engine/src/ccd, private): touching at the start (the
// exact per-frame test), else the earliest contact of its vertex-face and edge-edge queries.

#include "ccd/inclusion.hpp"

#include <array>

namespace collidescope::ccd {

/// The two triangles at both ends: a[i] is corner i's path; ia, ib the vertex indices (used
/// only when `self`: the self rule).
struct PairMotion {
    std::array<Path, 3> a, b;
    TriIndices ia{}, ib{};
    bool self = false;
};

/// What test_pair found.
struct PairOutcome {
    bool contact = false;
    double toi = 1;
    bool start_contact = false;  ///< touching at t = 0 (toi 0)
    bool end_contact = false;    ///< touching at t = 1 (computed only for a contact)
    bool resolved = true;
    std::uint32_t queries = 0;   ///< primitive queries run (past their box test)
    std::uint64_t boxes = 0;
};

/// Whether the pair touches during the interval, and from when. Of one object (`self`),
/// features that share a vertex index are not queried and the ends use the self rule.
PairOutcome test_pair(const PairMotion& motion, double tolerance, std::uint32_t max_boxes);

}  // namespace collidescope::ccd
