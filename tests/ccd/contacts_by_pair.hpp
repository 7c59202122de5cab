#pragma once
// An interval's contacts by triangle pair, for comparing a detector with the reference
// (tests/ccd's random and whole-scene tests).

#include "collidescope/between_frames.hpp"

#include <map>

namespace collidescope::testing {

/// What one contact reported, without its pair.
struct Contact {
    double toi;
    bool pass_through;
    bool resolved;
};

/// The contacts of `r` by pair.
inline std::map<TrianglePair, Contact> contacts_by_pair(const IntervalResult& r) {
    std::map<TrianglePair, Contact> out;
    for (const IntervalContact& c : r.contacts) out[c.pair] = {c.toi, c.pass_through, c.resolved};
    return out;
}

}  // namespace collidescope::testing
