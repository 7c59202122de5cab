#pragma once
/// An independent, slow, obviously correct reference for the triangle tests, in exact
/// rational arithmetic (GMP). It shares no code with engine/src/geometry: intersection is
/// decided as the feasibility of a linear program over barycentric coordinates, solved by
/// a textbook simplex (Bland's rule) on mpq_class.
///
///   T1 ∩ T2 != ∅  iff  exists l, m >= 0:  sum l_i = 1, sum m_j = 1, sum l_i a_i = sum m_j b_j.
///
/// The self-collision rule (an intersection point outside the hull H of the shared vertices)
/// is decided by maximising, over T1 ∩ T2, each of a finite set of linear functionals whose
/// half-spaces {f <= max_H f} cut out H exactly: a point leaves H iff some f exceeds its max.

#include "collidescope/types.hpp"

#include <array>

namespace collidescope::testing {

bool reference_triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

bool reference_self_collide(const TriIndices& ia, const std::array<Vec3, 3>& pa,
                            const TriIndices& ib, const std::array<Vec3, 3>& pb);

}  // namespace collidescope::testing
