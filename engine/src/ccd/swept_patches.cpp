// The swept patch test (swept_patches.hpp). Rounding: a difference of two doubles has the
// exact sign, so sign conditions on coordinate differences are exact. A 2 x 2 cross product
// of rounded differences, e_i f_j - e_j f_i, errs by at most 4u (|e_i f_j| + |e_j f_i|)
// (u = 2^-53: u on each difference, u on each product, u on the subtraction), a sum of two
// such by at most 5u times their magnitudes; a 2D dot product with a direction d of
// coordinates at most L, and the difference of two, by at most 4u L |d|_1. Every test below
// asks for a margin of 16u times the magnitude (plus a few subnormals against underflow); a
// product that overflows makes its bound infinite, or its value not finite: nothing is proven.

#include "ccd/swept_patches.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::ccd {
namespace {

constexpr double k_margin = 16 * (std::numeric_limits<double>::epsilon() / 2);
constexpr double k_underflow = 64 * std::numeric_limits<double>::denorm_min();

// The sign (+1, -1; 0 when not proven) of the quadratic cross2(e(t), f(t)) on [0, 1], for e and
// f moving linearly from (e0, f0) to (e1, f1), in the coordinates (i, j): from its Bernstein
// coefficients c00, (c01 + c10) / 2 and c11.
int swept_cross_sign(const Vec3& e0, const Vec3& f0, const Vec3& e1, const Vec3& f1, int i, int j) {
    const auto cross = [&](const Vec3& e, const Vec3& f, double& magnitude) {
        const double p = e[i] * f[j], q = e[j] * f[i];
        magnitude = std::abs(p) + std::abs(q);
        return p - q;
    };
    double m00, m11, m01, m10;
    const double c00 = cross(e0, f0, m00), c11 = cross(e1, f1, m11);
    const double mid = cross(e0, f1, m01) + cross(e1, f0, m10);
    const double b00 = k_margin * m00 + k_underflow, b11 = k_margin * m11 + k_underflow;
    const double bmid = k_margin * (m01 + m10) + k_underflow;
    if (c00 > b00 && c11 > b11 && mid > bmid) return 1;
    if (c00 < -b00 && c11 < -b11 && mid < -bmid) return -1;
    return 0;
}

int compare(double x, double y) { return (x > y) - (x < y); }

// The loop's corners projected, at both ends.
struct SweptLoop {
    std::span<const std::uint32_t> loop;
    std::span<const Vec3> from, to;
    int i, j;

    std::size_t size() const { return loop.size(); }
    const Vec3& at(std::size_t k, int end) const { return (end == 0 ? from : to)[loop[k % loop.size()]]; }
};

// Edge k (corner k to k + 1) keeps a positive length: on some axis the coordinate difference,
// linear in t, has one strict sign at both ends.
bool keeps_length(const SweptLoop& l, std::size_t k) {
    for (const int c : {l.i, l.j}) {
        const int s0 = compare(l.at(k + 1, 0)[c], l.at(k, 0)[c]);
        if (s0 != 0 && s0 == compare(l.at(k + 1, 1)[c], l.at(k, 1)[c])) return true;
    }
    return false;
}

// Consecutive edges (x, a) and (a, b), a = corner k, never fold back (share a point other than
// a): x and b on strictly opposite sides of a along some axis throughout, or the three
// corners never collinear.
bool never_folds(const SweptLoop& l, std::size_t k) {
    const std::size_t n = l.size();
    const std::size_t x = (k + n - 1) % n, b = (k + 1) % n;
    for (const int c : {l.i, l.j}) {
        const int sx0 = compare(l.at(x, 0)[c], l.at(k, 0)[c]), sb0 = compare(l.at(b, 0)[c], l.at(k, 0)[c]);
        const int sx1 = compare(l.at(x, 1)[c], l.at(k, 1)[c]), sb1 = compare(l.at(b, 1)[c], l.at(k, 1)[c]);
        if (sx0 != 0 && sx0 == sx1 && sb0 == -sx0 && sb1 == -sx0) return true;
    }
    return swept_cross_sign(l.at(x, 0) - l.at(k, 0), l.at(b, 0) - l.at(k, 0), l.at(x, 1) - l.at(k, 1),
                            l.at(b, 1) - l.at(k, 1), l.i, l.j) != 0;
}

// Edges e and f stay apart along the fixed 2D direction (dx, dy) (coordinates i, j): one's
// two corners below the other's at both ends, beyond the rounding bound. The direction is
// scaled to a largest component of 1 (any direction will do), which keeps the products within
// range; a value that is not finite decides nothing.
bool apart_along(const SweptLoop& l, std::size_t e, std::size_t f, double dx, double dy) {
    const double scale = std::max(std::abs(dx), std::abs(dy));
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    dx /= scale;
    dy /= scale;
    double largest = 0;
    for (const std::size_t k : {e, e + 1, f, f + 1}) {
        for (int end = 0; end < 2; ++end) {
            largest = std::max({largest, std::abs(l.at(k, end)[l.i]), std::abs(l.at(k, end)[l.j])});
        }
    }
    const double bound = k_margin * largest * (std::abs(dx) + std::abs(dy)) + k_underflow;
    bool e_below = true, f_below = true;
    for (int end = 0; end < 2; ++end) {
        const auto along = [&](std::size_t k) { return l.at(k, end)[l.i] * dx + l.at(k, end)[l.j] * dy; };
        const double e0 = along(e), e1 = along(e + 1), f0 = along(f), f1 = along(f + 1);
        if (!std::isfinite(e0) || !std::isfinite(e1) || !std::isfinite(f0) || !std::isfinite(f1)) return false;
        e_below = e_below && std::min(f0, f1) - std::max(e0, e1) > bound;
        f_below = f_below && std::min(e0, e1) - std::max(f0, f1) > bound;
    }
    return e_below || f_below;
}

// Non-consecutive edges e and f never share a point: apart along the normal or the direction
// of one of them, at either end (the candidates of the separating axis theorem for two
// segments; the directions part collinear edges, such as those along a sheet's straight border).
bool stay_apart(const SweptLoop& l, std::size_t e, std::size_t f) {
    for (int end = 0; end < 2; ++end) {
        for (const std::size_t k : {e, f}) {
            const double dx = l.at(k + 1, end)[l.i] - l.at(k, end)[l.i];
            const double dy = l.at(k + 1, end)[l.j] - l.at(k, end)[l.j];
            if (apart_along(l, e, f, -dy, dx) || apart_along(l, e, f, dx, dy)) return true;
        }
    }
    return false;
}

struct EdgeBox {
    double lo[2], hi[2];
    std::uint32_t edge;
};

}  // namespace

std::uint8_t swept_triangle_sides(const TriIndices& t, std::span<const Vec3> from, std::span<const Vec3> to) {
    const Vec3 e0 = from[t[1]] - from[t[0]], f0 = from[t[2]] - from[t[0]];
    const Vec3 e1 = to[t[1]] - to[t[0]], f1 = to[t[2]] - to[t[0]];
    std::uint8_t bits = 0;
    for (int k = 0; k < 3; ++k) {
        const int sign = swept_cross_sign(e0, f0, e1, f1, (k + 1) % 3, (k + 2) % 3);
        if (sign > 0) bits |= static_cast<std::uint8_t>(1u << (2 * k));
        if (sign < 0) bits |= static_cast<std::uint8_t>(2u << (2 * k));
    }
    return bits;
}

void swept_node_sides(const bvh::Tree& tree, std::span<const Vec3> from, std::span<const Vec3> to,
                      std::vector<std::uint8_t>& sides) {
    const std::size_t slots = tree.leaf_triangles.size();
    std::vector<std::uint8_t> by_slot(slots);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, slots, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t s = r.begin(); s != r.end(); ++s) by_slot[s] = swept_triangle_sides(tree.leaf_triangles[s], from, to);
    });
    sides.assign(tree.nodes.size(), 0);
    for (std::size_t k = tree.nodes.size(); k-- > 0;) {  // preorder backwards: children first
        const bvh::Node& node = tree.nodes[k];
        if (node.is_leaf()) {
            std::uint8_t s = 0x3f;
            for (std::uint32_t slot = node.index; slot < node.index + node.count; ++slot) s &= by_slot[slot];
            sides[k] = s;
        } else {
            sides[k] = sides[k + 1] & sides[node.index];
        }
    }
}

bool swept_loop_stays_simple(std::span<const std::uint32_t> loop, std::span<const Vec3> from, std::span<const Vec3> to,
                             int drop) {
    const SweptLoop l{loop, from, to, (drop + 1) % 3, (drop + 2) % 3};
    const std::size_t n = l.size();
    if (n < 3) return false;
    for (std::size_t k = 0; k < n; ++k) {
        if (!keeps_length(l, k) || !never_folds(l, k)) return false;
    }
    // Non-consecutive edges whose swept boxes (the box of both corners at both ends, which
    // holds the edge throughout) meet, found by sorting the boxes along the first coordinate.
    std::vector<EdgeBox> boxes(n);
    for (std::size_t k = 0; k < n; ++k) {
        EdgeBox& b = boxes[k];
        b.edge = static_cast<std::uint32_t>(k);
        for (int a = 0; a < 2; ++a) {
            const int c = a == 0 ? l.i : l.j;
            b.lo[a] = std::min({l.at(k, 0)[c], l.at(k, 1)[c], l.at(k + 1, 0)[c], l.at(k + 1, 1)[c]});
            b.hi[a] = std::max({l.at(k, 0)[c], l.at(k, 1)[c], l.at(k + 1, 0)[c], l.at(k + 1, 1)[c]});
        }
    }
    std::sort(boxes.begin(), boxes.end(), [](const EdgeBox& a, const EdgeBox& b) { return a.lo[0] < b.lo[0]; });
    for (std::size_t s = 0; s < n; ++s) {
        for (std::size_t t = s + 1; t < n && boxes[t].lo[0] <= boxes[s].hi[0]; ++t) {
            if (boxes[t].lo[1] > boxes[s].hi[1] || boxes[s].lo[1] > boxes[t].hi[1]) continue;
            const std::size_t e = std::min(boxes[s].edge, boxes[t].edge), f = std::max(boxes[s].edge, boxes[t].edge);
            if (f == e + 1 || (e == 0 && f == n - 1)) continue;  // consecutive: never_folds
            if (!stay_apart(l, e, f)) return false;
        }
    }
    return true;
}

bool swept_patch_is_embedded(const bvh::Tree& tree, std::span<const std::uint8_t> sides, std::uint32_t node,
                             std::span<const Vec3> from, std::span<const Vec3> to) {
    const bvh::SurfacePatches& p = tree.patches;
    const std::uint8_t s = sides[node];
    if (s == 0 || p.loop_size[node] == 0) return false;
    const std::span<const std::uint32_t> loop(p.loop_vertices.data() + p.loop_begin[node], p.loop_size[node]);
    for (int k = 0; k < 3; ++k) {
        if (((s >> (2 * k)) & 3u) != 0 && swept_loop_stays_simple(loop, from, to, k)) return true;
    }
    return false;
}

}  // namespace collidescope::ccd
