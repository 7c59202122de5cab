#pragma once
/// Seeded generators of triangle pairs biased toward contact: touching, grazing, coplanar,
/// degenerate and on-a-grid configurations where a float filter alone would be wrong.

#include "collidescope/types.hpp"

#include <array>
#include <cstdint>
#include <random>
#include <string>

namespace collidescope::testing {

struct TrianglePairCase {
    std::array<Vec3, 3> a;
    std::array<Vec3, 3> b;
    std::string kind;  ///< which generator made it, for failure messages and per-kind rates
};

/// One random pair; the mix of kinds is fixed, every kind is biased toward near contact.
TrianglePairCase random_near_contact_pair(std::mt19937_64& rng);

/// Two triangles of one object sharing one or two vertex indices (sometimes a repeated index
/// inside one triangle), over a small pool of grid-like positions.
struct SelfPairCase {
    TriIndices ia, ib;
    std::array<Vec3, 3> pa, pb;
};
SelfPairCase random_self_pair(std::mt19937_64& rng);

/// Prints "a0 a1 a2 | b0 b1 b2" with full precision (hexfloat) for failure messages.
std::string describe(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

}  // namespace collidescope::testing
