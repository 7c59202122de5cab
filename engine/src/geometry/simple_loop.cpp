// projected_loop_is_simple: every edge of positive length, then every pair of edges tested,
// either all pairs (short loops, and the reference) or only pairs that share a cell of a
// uniform grid laid over the loop's box. The grid is conservative: a cell index is a
// monotone function of a coordinate (a subtraction and a multiplication, both rounded
// monotonically, then a truncation), so two edges that share a point share the cell of that
// point. A pair sharing several cells is tested once, in the lowest cell of the overlap.

#include "geometry/simple_loop.hpp"

#include "collidescope/geometry.hpp"
#include "geometry/contact_tests.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace collidescope::contact {
namespace {

constexpr std::size_t kBruteForceEdges = 32;

struct Projection {
    std::span<const std::uint32_t> loop;
    std::span<const Vec3> vertices;
    int drop, i, j;

    Projection(std::span<const std::uint32_t> l, std::span<const Vec3> v, int d)
        : loop(l), vertices(v), drop(d), i((d + 1) % 3), j((d + 2) % 3) {}
    std::size_t size() const { return loop.size(); }
    const Vec3& corner(std::size_t k) const { return vertices[loop[k % loop.size()]]; }
};

/// Consecutive edges (x, a) and (a, b) of positive length share a point other than a iff the
/// three corners are collinear and b lies on x's side of a (exact: signs of coordinates).
bool folds_back(const Projection& p, const Vec3& x, const Vec3& a, const Vec3& b) {
    if (orient2d(x, a, b, p.drop) != 0) return false;
    for (const int k : {p.i, p.j}) {
        const int sx = (x[k] > a[k]) - (x[k] < a[k]);
        const int sb = (b[k] > a[k]) - (b[k] < a[k]);
        if (sx != sb) return false;
    }
    return true;
}

bool boxes_apart(const Projection& p, std::size_t e, std::size_t f) {
    for (const int k : {p.i, p.j}) {
        const double e0 = p.corner(e)[k], e1 = p.corner(e + 1)[k];
        const double f0 = p.corner(f)[k], f1 = p.corner(f + 1)[k];
        if (std::max(e0, e1) < std::min(f0, f1) || std::max(f0, f1) < std::min(e0, e1)) return true;
    }
    return false;
}

/// True when edges e < f (edge k runs from corner k to corner k + 1) share a point they
/// must not share.
bool conflict(const Projection& p, std::size_t e, std::size_t f) {
    const std::size_t n = p.size();
    if (f == e + 1) return folds_back(p, p.corner(e), p.corner(f), p.corner(f + 1));
    if (e == 0 && f == n - 1) return folds_back(p, p.corner(f), p.corner(0), p.corner(1));
    if (boxes_apart(p, e, f)) return false;
    return segments_intersect_2d(p.corner(e), p.corner(e + 1), p.corner(f), p.corner(f + 1), p.drop);
}

bool edges_have_length(const Projection& p) {
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec3& a = p.corner(k);
        const Vec3& b = p.corner(k + 1);
        if (a[p.i] == b[p.i] && a[p.j] == b[p.j]) return false;
    }
    return true;
}

bool all_pairs_apart(const Projection& p) {
    for (std::size_t e = 0; e < p.size(); ++e)
        for (std::size_t f = e + 1; f < p.size(); ++f)
            if (conflict(p, e, f)) return false;
    return true;
}

struct CellRange {
    std::uint32_t x0, x1, y0, y1;
};

bool grid_pairs_apart(const Projection& p) {
    const std::size_t n = p.size();
    double lo[2] = {p.corner(0)[p.i], p.corner(0)[p.j]}, hi[2] = {lo[0], lo[1]};
    for (std::size_t k = 1; k < n; ++k) {
        const double c[2] = {p.corner(k)[p.i], p.corner(k)[p.j]};
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
    }
    const auto side = static_cast<std::uint32_t>(std::max(1.0, std::floor(std::sqrt(static_cast<double>(n)))));
    double scale[2];
    for (int a = 0; a < 2; ++a) {
        scale[a] = hi[a] > lo[a] ? side / (hi[a] - lo[a]) : 0.0;
        if (!std::isfinite(scale[a])) return all_pairs_apart(p);
    }
    const auto cell = [&](int a, double x) -> std::uint32_t {
        const double c = (x - lo[a]) * scale[a];  // >= 0, monotone in x
        return c >= side ? side - 1 : static_cast<std::uint32_t>(c);
    };
    std::vector<CellRange> ranges(n);
    std::size_t entries = 0;
    for (std::size_t e = 0; e < n; ++e) {
        const Vec3& a = p.corner(e);
        const Vec3& b = p.corner(e + 1);
        CellRange& r = ranges[e];
        r.x0 = cell(0, std::min(a[p.i], b[p.i])), r.x1 = cell(0, std::max(a[p.i], b[p.i]));
        r.y0 = cell(1, std::min(a[p.j], b[p.j])), r.y1 = cell(1, std::max(a[p.j], b[p.j]));
        entries += std::size_t{r.x1 - r.x0 + 1} * (r.y1 - r.y0 + 1);
    }
    if (entries > 16 * n) return all_pairs_apart(p);  // long edges: the grid would not pay
    std::vector<std::uint32_t> start(std::size_t{side} * side + 1, 0);
    for (const CellRange& r : ranges)
        for (std::uint32_t y = r.y0; y <= r.y1; ++y)
            for (std::uint32_t x = r.x0; x <= r.x1; ++x) ++start[y * side + x + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1), slots(entries);
    for (std::uint32_t e = 0; e < n; ++e) {
        const CellRange& r = ranges[e];
        for (std::uint32_t y = r.y0; y <= r.y1; ++y)
            for (std::uint32_t x = r.x0; x <= r.x1; ++x) slots[fill[y * side + x]++] = e;
    }
    for (std::uint32_t y = 0; y < side; ++y) {
        for (std::uint32_t x = 0; x < side; ++x) {
            const std::uint32_t c = y * side + x;
            for (std::uint32_t s = start[c]; s < start[c + 1]; ++s) {
                for (std::uint32_t t = s + 1; t < start[c + 1]; ++t) {
                    const CellRange& a = ranges[slots[s]];
                    const CellRange& b = ranges[slots[t]];
                    if (std::max(a.x0, b.x0) != x || std::max(a.y0, b.y0) != y) continue;  // tested elsewhere
                    const std::size_t e = std::min(slots[s], slots[t]), f = std::max(slots[s], slots[t]);
                    if (conflict(p, e, f)) return false;
                }
            }
        }
    }
    return true;
}

}  // namespace

bool projected_loop_is_simple(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices, int drop) {
    const Projection p(loop, vertices, drop);
    if (p.size() < 3 || !edges_have_length(p)) return false;
    return p.size() <= kBruteForceEdges ? all_pairs_apart(p) : grid_pairs_apart(p);
}

bool projected_loop_is_simple_reference(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices,
                                        int drop) {
    const Projection p(loop, vertices, drop);
    if (p.size() < 3 || !edges_have_length(p)) return false;
    for (std::size_t e = 0; e < p.size(); ++e)
        for (std::size_t f = e + 1; f < p.size(); ++f) {
            const bool adjacent = f == e + 1 || (e == 0 && f == p.size() - 1);
            if (adjacent ? conflict(p, e, f)
                         : segments_intersect_2d(p.corner(e), p.corner(e + 1), p.corner(f), p.corner(f + 1), drop))
                return false;
        }
    return true;
}

}  // namespace collidescope::contact
