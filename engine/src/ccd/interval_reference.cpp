// Interval bisection that cannot miss: see interval_reference.hpp.

#include "ccd/interval_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace collidescope::ccd::reference {
namespace {

// A closed interval, widened outward after every operation (a correctly rounded result is
// within half an ulp of the exact one).
struct Interval {
    double lo, hi;
};

// One ulp (at least) outward: |x| 2^-52 is at least an ulp of x, and x plus it rounds to a
// double no nearer than the next one (round to nearest is monotonic and x's neighbour is a
// double); the smallest subnormal covers x = 0. std::nextafter gives exactly one ulp and was
// two thirds of the reference's time.
double down(double x) { return x - (std::abs(x) * 0x1p-52 + std::numeric_limits<double>::denorm_min()); }
double up(double x) { return x + (std::abs(x) * 0x1p-52 + std::numeric_limits<double>::denorm_min()); }

Interval point(double x) { return {x, x}; }
Interval operator+(Interval a, Interval b) { return {down(a.lo + b.lo), up(a.hi + b.hi)}; }
Interval operator-(Interval a, Interval b) { return {down(a.lo - b.hi), up(a.hi - b.lo)}; }
Interval operator*(Interval a, Interval b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {down(*std::min_element(p, p + 4)), up(*std::max_element(p, p + 4))};
}

// A point moving from x[0] to x[1], at the times of `t`, one axis.
Interval moving(const Path& x, int axis, Interval t) { return point(x[0][axis]) + t * (point(x[1][axis]) - point(x[0][axis])); }

struct Box {
    double t0, t1, u0, u1, v0, v1;
    std::uint32_t level = 0;  ///< halvings from the whole domain
};

// F over `box`, axis k: the formula of each query as written.
using Evaluate = Interval (*)(const std::array<const Path*, 4>&, int, Interval, Interval, Interval);

Interval vertex_face_value(const std::array<const Path*, 4>& x, int k, Interval t, Interval u, Interval v) {
    const Interval p = moving(*x[0], k, t), a = moving(*x[1], k, t), b = moving(*x[2], k, t), c = moving(*x[3], k, t);
    return p - (a + u * (b - a) + v * (c - a));
}

Interval edge_edge_value(const std::array<const Path*, 4>& x, int k, Interval t, Interval u, Interval v) {
    const Interval p0 = moving(*x[0], k, t), p1 = moving(*x[1], k, t), q0 = moving(*x[2], k, t), q1 = moving(*x[3], k, t);
    return (p0 + u * (p1 - p0)) - (q0 + v * (q1 - q0));
}

QueryResult solve(const std::array<const Path*, 4>& x, Evaluate evaluate, bool simplex, const QueryConfig& config,
                  Times times) {
    QueryResult result;
    std::vector<Box> heap{{times.first, std::min(1.0, config.t_max), 0, 1, 0, 1, 0}};
    const auto later = [](const Box& a, const Box& b) { return a.t0 > b.t0 || (a.t0 == b.t0 && a.level < b.level); };  // as inclusion.cpp
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Box box = heap.back();
        heap.pop_back();
        if (box.t0 > config.t_max) break;
        if (simplex && box.u0 + box.v0 > 1) continue;  // no point of the box in the triangle
        if (++result.boxes > config.max_boxes) {
            result.hit = true;
            result.toi = box.t0;
            result.resolved = false;
            return result;
        }
        bool excluded = false, within = true;
        for (int k = 0; k < 3; ++k) {
            const Interval value = evaluate(x, k, {box.t0, box.t1}, {box.u0, box.u1}, {box.v0, box.v1});
            excluded = excluded || value.lo > times.margin || value.hi < -times.margin;
            within = within && value.lo >= -config.tolerance && value.hi <= config.tolerance;
        }
        if (excluded) continue;
        if (within) {
            result.hit = true;
            result.toi = box.t0;
            return result;
        }
        const double t = 0.5 * (box.t0 + box.t1), u = 0.5 * (box.u0 + box.u1), v = 0.5 * (box.v0 + box.v1);
        if (!(box.t0 < t && t < box.t1) && !(box.u0 < u && u < box.u1) && !(box.v0 < v && v < box.v1)) {
            result.hit = true;  // cannot halve any more: conservatively a contact
            result.toi = box.t0;
            result.resolved = false;
            return result;
        }
        for (int child = 0; child < 8; ++child) {
            heap.push_back({child & 1 ? t : box.t0, child & 1 ? box.t1 : t, child & 2 ? u : box.u0, child & 2 ? box.u1 : u,
                            child & 4 ? v : box.v0, child & 4 ? box.v1 : v, box.level + 1});
            std::push_heap(heap.begin(), heap.end(), later);
        }
    }
    return result;
}

}  // namespace

QueryResult vertex_face(const Path& p, const Path& a, const Path& b, const Path& c, const QueryConfig& config,
                        Times times) {
    return solve({&p, &a, &b, &c}, vertex_face_value, true, config, times);
}

QueryResult edge_edge(const Path& p0, const Path& p1, const Path& q0, const Path& q1, const QueryConfig& config,
                      Times times) {
    return solve({&p0, &p1, &q0, &q1}, edge_edge_value, false, config, times);
}

}  // namespace collidescope::ccd::reference
