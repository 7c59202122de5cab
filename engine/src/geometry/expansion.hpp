#pragma once
/// Exact floating-point expansion arithmetic (Shewchuk, "Adaptive Precision Floating-Point
/// Arithmetic and Fast Robust Geometric Predicates", 1997), for the predicates' exact path.
///
/// An expansion is an array of doubles, nonoverlapping and ordered by increasing magnitude,
/// with zero components removed; its value is their exact sum and its sign the sign of its
/// last component. Every operation here is exact as long as nothing underflows or
/// overflows; predicates.cpp only takes this path when the inputs' magnitudes guarantee that.
/// Requires IEEE double arithmetic with round-to-nearest-even and no contraction (the build
/// sets -ffp-contract=off, which Dekker's product needs).
/// Output arrays must not alias inputs and must hold the documented number of terms.

#include <cmath>

namespace collidescope::exact {

/// a + b = sum + err exactly.
inline void two_sum(double a, double b, double& sum, double& err) {
    sum = a + b;
    const double b_virtual = sum - a;
    const double a_virtual = sum - b_virtual;
    err = (a - a_virtual) + (b - b_virtual);
}

/// a - b = diff + err exactly.
inline void two_diff(double a, double b, double& diff, double& err) { two_sum(a, -b, diff, err); }

/// a = hi + lo with both halves of at most 26 significant bits (Dekker's split).
inline void split(double a, double& hi, double& lo) {
    constexpr double kSplitter = 134217729.0;  // 2^27 + 1
    const double c = kSplitter * a;
    const double big = c - a;
    hi = c - big;
    lo = a - hi;
}

/// a * b = product + err exactly (Dekker's product; std::fma would be a libm call on
/// baseline x86-64, several times slower).
inline void two_product(double a, double b, double& product, double& err) {
    product = a * b;
    double ahi, alo, bhi, blo;
    split(a, ahi, alo);
    split(b, bhi, blo);
    const double err1 = product - ahi * bhi;
    const double err2 = err1 - alo * bhi;
    const double err3 = err2 - ahi * blo;
    err = alo * blo - err3;
}

/// h = e + f (Shewchuk's FAST-EXPANSION-SUM-ZEROELIM, a linear merge). h holds ne + nf.
inline int sum(const double* e, int ne, const double* f, int nf, double* h) {
    if (ne == 0 && nf == 0) return 0;
    int ei = 0, fi = 0, hn = 0;
    double q;
    const auto next = [&]() {
        if (fi >= nf || (ei < ne && std::fabs(e[ei]) < std::fabs(f[fi]))) return e[ei++];
        return f[fi++];
    };
    q = next();
    while (ei < ne || fi < nf) {
        double s, err;
        two_sum(q, next(), s, err);
        q = s;
        if (err != 0) h[hn++] = err;
    }
    if (q != 0 || hn == 0) h[hn++] = q;
    return hn;
}

/// h = e * b (SCALE-EXPANSION-ZEROELIM). h holds 2 * ne.
inline int scale(const double* e, int ne, double b, double* h) {
    if (ne == 0) return 0;
    int hn = 0;
    double q, err;
    two_product(e[0], b, q, err);
    if (err != 0) h[hn++] = err;
    for (int i = 1; i < ne; ++i) {
        double p, p_err, s, s_err;
        two_product(e[i], b, p, p_err);
        two_sum(q, p_err, s, s_err);
        if (s_err != 0) h[hn++] = s_err;
        two_sum(p, s, q, err);
        if (err != 0) h[hn++] = err;
    }
    if (q != 0 || hn == 0) h[hn++] = q;
    return hn;
}

/// h = e * f for a short f (nf <= 2): the sum of e scaled by each of f's terms.
/// h holds 4 * ne; `scratch` holds 4 * ne.
inline int product(const double* e, int ne, const double* f, int nf, double* h, double* scratch) {
    if (nf == 1) return scale(e, ne, f[0], h);
    const int n0 = scale(e, ne, f[0], scratch);
    const int n1 = scale(e, ne, f[1], scratch + n0);
    return sum(scratch, n0, scratch + n0, n1, h);
}

/// -1, 0 or +1: the sign of an expansion's value.
inline int sign(const double* e, int ne) {
    if (ne == 0) return 0;
    return e[ne - 1] > 0 ? 1 : (e[ne - 1] < 0 ? -1 : 0);
}

inline void negate(double* e, int ne) {
    for (int i = 0; i < ne; ++i) e[i] = -e[i];
}

}  // namespace collidescope::exact
