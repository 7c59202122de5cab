#include "support/random_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace collidescope::testing {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int integer(std::mt19937_64& rng, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
}
/// A float32 coordinate, as most meshes store them.
double f32(double x) { return round_to_float32(x); }

Vec3 random_point(std::mt19937_64& rng) {
    return {f32(uniform(rng, 0, 1)), f32(uniform(rng, 0, 1)), f32(uniform(rng, 0, 1))};
}
Vec3 grid_point(std::mt19937_64& rng, int n) {
    return {double(integer(rng, 0, n)), double(integer(rng, 0, n)), double(integer(rng, 0, n))};
}

/// A point of triangle t: a corner, an edge midpoint or an interior point.
Vec3 point_on(const std::array<Vec3, 3>& t, std::mt19937_64& rng) {
    switch (integer(rng, 0, 2)) {
        case 0: return t[integer(rng, 0, 2)];
        case 1: {
            const int i = integer(rng, 0, 2);
            return (t[i] + t[(i + 1) % 3]) * 0.5;  // exact: halving a sum of floats
        }
        default: {
            const double u = uniform(rng, 0, 1), v = uniform(rng, 0, 1 - u);
            return t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
        }
    }
}

/// B has one corner at (or within 10^-k of) a point of A, the others spread around it.
TrianglePairCase touching(std::mt19937_64& rng) {
    TrianglePairCase c;
    c.kind = "touching";
    c.a = {random_point(rng), random_point(rng), random_point(rng)};
    const Vec3 x = point_on(c.a, rng);
    const double offset = integer(rng, 0, 2) == 0 ? 0.0 : std::pow(10.0, -integer(rng, 1, 12));
    const Vec3 dir(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    c.b[0] = x + offset * dir;
    for (int i = 1; i < 3; ++i) c.b[i] = x + 0.5 * Vec3(random_point(rng) - Vec3(0.5, 0.5, 0.5));
    return c;
}

/// Both triangles in one plane: z = const, or the integer plane x + y + z = 6.
TrianglePairCase coplanar(std::mt19937_64& rng) {
    TrianglePairCase c;
    c.kind = "coplanar";
    if (integer(rng, 0, 1) == 0) {
        const double z = f32(uniform(rng, -1, 1));
        for (auto* t : {&c.a, &c.b})
            for (auto& p : *t) p = Vec3(f32(uniform(rng, 0, 1)), f32(uniform(rng, 0, 1)), z);
    } else {
        for (auto* t : {&c.a, &c.b})
            for (auto& p : *t) {
                const int x = integer(rng, 0, 6), y = integer(rng, 0, 6 - x);
                p = Vec3(x, y, 6 - x - y);
            }
    }
    return c;
}

/// Small integer grid: shared corners, corners on edges, coplanar pieces, everywhere.
TrianglePairCase grid(std::mt19937_64& rng) {
    TrianglePairCase c;
    c.kind = "grid";
    for (auto* t : {&c.a, &c.b})
        for (auto& p : *t) p = grid_point(rng, 3);
    return c;
}

/// At least one triangle degenerate: collinear integer points or a repeated point.
TrianglePairCase degenerate(std::mt19937_64& rng) {
    TrianglePairCase c;
    c.kind = "degenerate";
    const auto make_flat = [&](std::array<Vec3, 3>& t) {
        const Vec3 base = grid_point(rng, 3);
        const Vec3 dir = grid_point(rng, 2) - Vec3(1, 1, 1);
        for (auto& p : t) p = base + integer(rng, -2, 2) * dir;
    };
    make_flat(c.a);
    if (integer(rng, 0, 1) == 0) make_flat(c.b);
    else
        for (auto& p : c.b) p = grid_point(rng, 3) - Vec3(1, 1, 1) + c.a[0];
    return c;
}

/// Two random triangles close together, float32 coordinates.
TrianglePairCase crossing(std::mt19937_64& rng) {
    TrianglePairCase c;
    c.kind = "crossing";
    const Vec3 shift(uniform(rng, -0.4, 0.4), uniform(rng, -0.4, 0.4), uniform(rng, -0.4, 0.4));
    for (auto& p : c.a) p = random_point(rng);
    for (auto& p : c.b) p = Vec3(f32(uniform(rng, 0, 1) + shift.x()), f32(uniform(rng, 0, 1) + shift.y()),
                                 f32(uniform(rng, 0, 1) + shift.z()));
    return c;
}

/// Scales a case near 1e-30 or 1e30: exactly by a power of two, or inexactly by 10^k.
void rescale(TrianglePairCase& c, std::mt19937_64& rng) {
    const int choice = integer(rng, 0, 9);
    if (choice >= 4) return;
    const double factor = choice == 0 ? 0x1p-100 : choice == 1 ? 0x1p100 : choice == 2 ? 1e-30 : 1e30;
    for (auto* t : {&c.a, &c.b})
        for (auto& p : *t) p *= factor;
    c.kind += choice < 2 ? "*2^k" : "*10^k";
}

}  // namespace

TrianglePairCase random_near_contact_pair(std::mt19937_64& rng) {
    TrianglePairCase c;
    switch (integer(rng, 0, 9)) {
        case 0: case 1: case 2: c = touching(rng); break;
        case 3: case 4: c = coplanar(rng); break;
        case 5: case 6: c = grid(rng); break;
        case 7: c = degenerate(rng); break;
        default: c = crossing(rng); break;
    }
    if (integer(rng, 0, 1) == 0) std::swap(c.a, c.b);
    rescale(c, rng);
    return c;
}

SelfPairCase random_self_pair(std::mt19937_64& rng) {
    std::array<Vec3, 6> pool;
    for (auto& p : pool) p = grid_point(rng, 2);
    if (integer(rng, 0, 3) == 0)  // sometimes off-grid float32 positions
        for (auto& p : pool) p = random_point(rng);
    SelfPairCase c;
    // Shared indices first, then distinct others; occasionally a repeated index.
    const int shared = integer(rng, 1, 2);
    std::array<std::uint32_t, 6> order = {0, 1, 2, 3, 4, 5};
    std::shuffle(order.begin(), order.end(), rng);
    c.ia = {order[0], shared == 2 ? order[1] : order[2], order[3]};
    c.ib = {order[0], shared == 2 ? order[1] : order[4], order[5]};
    if (integer(rng, 0, 9) == 0) c.ia[2] = c.ia[integer(rng, 0, 1)];
    std::shuffle(c.ia.begin(), c.ia.end(), rng);
    std::shuffle(c.ib.begin(), c.ib.end(), rng);
    for (int k = 0; k < 3; ++k) {
        c.pa[k] = pool[c.ia[k]];
        c.pb[k] = pool[c.ib[k]];
    }
    return c;
}

std::string describe(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    std::string out;
    char buffer[128];
    for (const auto* t : {&a, &b}) {
        for (const Vec3& p : *t) {
            std::snprintf(buffer, sizeof buffer, "(%a, %a, %a) ", p.x(), p.y(), p.z());
            out += buffer;
        }
        if (t == &a) out += "| ";
    }
    return out;
}

}  // namespace collidescope::testing
