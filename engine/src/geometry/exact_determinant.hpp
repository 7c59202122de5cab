#pragma once
// The exact value of a 3x3 determinant of doubles, with GMP rationals (engine/src/geometry,
// private): the predicates' last resort takes its sign; the regions' edge crossings take the
// value where rounding would move the crossing along the edge.

#include <gmp.h>

namespace collidescope {

/// `out` (initialised by the caller) = the determinant of rows[i][k] - shift[k] (shift = 0 when
/// null). Exact for any finite doubles: no underflow or overflow.
void determinant3_gmp(const double rows[3][3], const double* shift, mpq_t out);

}  // namespace collidescope
