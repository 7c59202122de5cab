// The exact 3x3 determinant (exact_determinant.hpp): rationals, expanded along row 0 with
// cyclic cofactors.

#include "exact_determinant.hpp"

namespace collidescope {

void determinant3_gmp(const double rows[3][3], const double* shift, mpq_t out) {
    mpq_t m[3][3], offset, t0, t1;
    mpq_inits(offset, t0, t1, nullptr);
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            mpq_init(m[i][k]);
            mpq_set_d(m[i][k], rows[i][k]);
            if (shift) {
                mpq_set_d(offset, shift[k]);
                mpq_sub(m[i][k], m[i][k], offset);
            }
        }
    }
    mpq_set_ui(out, 0, 1);
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        mpq_mul(t0, m[1][k1], m[2][k2]);
        mpq_mul(t1, m[1][k2], m[2][k1]);
        mpq_sub(t0, t0, t1);
        mpq_mul(t0, t0, m[0][k]);
        mpq_add(out, out, t0);
    }
    for (auto& row : m) {
        for (auto& cell : row) mpq_clear(cell);
    }
    mpq_clears(offset, t0, t1, nullptr);
}

}  // namespace collidescope
