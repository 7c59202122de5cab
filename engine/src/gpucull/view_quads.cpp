// Conservative per-triangle records for one view: pixel rectangles and depth bound planes.

#include "gpucull/view_quads.hpp"

#include "geometry/float32.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::gpucull {
namespace {

// Pixel coordinates and depth of a point: u, v on the two axes other than the view axis.
struct Projected {
    double x, y, z;
};

Projected project(const View& view, const Vec3& p) {
    const int u = (view.axis + 1) % 3;
    const int v = (view.axis + 2) % 3;
    const int d = view.axis;
    const Vec3 lo = view.bounds.min();
    const Vec3 extent = view.bounds.max() - lo;
    // A flat PCS along an axis has zero extent there; any positive scale then works.
    const auto scale = [](double e, double to) { return e > 0 ? to / e : 1.0; };
    return {(p[u] - lo[u]) * scale(extent[u], view.width), (p[v] - lo[v]) * scale(extent[v], view.height),
            0.25 + (p[d] - lo[d]) * scale(extent[d], 0.5)};
}

// The edge lines of the projected triangle, unit outward normals. Nearly edge-on (or a segment
// or point) the normals are meaningless and the box alone decides coverage.
void set_edges(TriangleQuad& quad, const Projected (&q)[3], int size) {
    const double area2 = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
    double longest = 0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, std::hypot(q[(i + 1) % 3].x - q[i].x, q[(i + 1) % 3].y - q[i].y));
    // Evaluation error of n.p + d in float32 (terms up to ~1.5 size pixels, a few roundings of
    // 2^-24 each, plus rounding n and d to float) is below 2e-6 size; double error is far less.
    quad.edge_margin = static_cast<float>(1e-3 + 2e-6 * size);
    if (!(std::abs(area2) > 1e-6 * longest * longest) || longest == 0) return;  // edges stay zero
    for (int i = 0; i < 3; ++i) {
        const Projected& p = q[i];
        const Projected& r = q[(i + 1) % 3];
        const double length = std::hypot(r.x - p.x, r.y - p.y);
        double nx = (r.y - p.y) / length, ny = -(r.x - p.x) / length;
        if (area2 < 0) { nx = -nx; ny = -ny; }  // point away from the third corner
        quad.edges[i][0] = static_cast<float>(nx);
        quad.edges[i][1] = static_cast<float>(ny);
        quad.edges[i][2] = static_cast<float>(-(nx * p.x + ny * p.y));
    }
}

}  // namespace

TriangleQuad make_quad(const View& view, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       std::uint32_t id) {
    const Projected q[3] = {project(view, p0), project(view, p1), project(view, p2)};
    TriangleQuad quad{};
    quad.id = id;
    // Whole pixels: pixel i covers [i, i + 1], so a box from xmin to xmax touches pixels
    // ceil(xmin) - 1 .. floor(xmax) (a box reaching exactly x = i touches pixels i - 1 and i).
    // k_pixel_slack (far above the double rounding of the projection) keeps that true.
    constexpr double k_pixel_slack = 1e-6;
    quad.x0 = static_cast<float>(std::ceil(std::min({q[0].x, q[1].x, q[2].x}) - k_pixel_slack) - 1);
    quad.y0 = static_cast<float>(std::ceil(std::min({q[0].y, q[1].y, q[2].y}) - k_pixel_slack) - 1);
    quad.x1 = static_cast<float>(std::floor(std::max({q[0].x, q[1].x, q[2].x}) + k_pixel_slack) + 1);
    quad.y1 = static_cast<float>(std::floor(std::max({q[0].y, q[1].y, q[2].y}) + k_pixel_slack) + 1);
    set_edges(quad, q, std::max(view.width, view.height));
    quad.zlo = float32_below(std::min({q[0].z, q[1].z, q[2].z}));
    quad.zhi = float32_above(std::max({q[0].z, q[1].z, q[2].z}));

    // The plane z = a x + b y + c through the projected corners. Seen nearly edge-on its
    // coefficients are unbounded, and the flat range [zlo, zhi] is the bound instead.
    const double ex1 = q[1].x - q[0].x, ey1 = q[1].y - q[0].y, ez1 = q[1].z - q[0].z;
    const double ex2 = q[2].x - q[0].x, ey2 = q[2].y - q[0].y, ez2 = q[2].z - q[0].z;
    const double area2 = ex1 * ey2 - ex2 * ey1;
    const double size2 = std::max({ex1 * ex1 + ey1 * ey1, ex2 * ex2 + ey2 * ey2, 1e-300});
    if (!(std::abs(area2) > 1e-6 * size2)) {
        quad.a = quad.b = 0;
        quad.c = 0.5f * (quad.zlo + quad.zhi);
        quad.margin = 1;  // clamping to [zlo, zhi] decides
        return quad;
    }
    const double a = (ez1 * ey2 - ez2 * ey1) / area2;
    const double b = (ex1 * ez2 - ex2 * ez1) / area2;
    const double c = q[0].z - a * q[0].x - b * q[0].y;
    quad.a = static_cast<float>(a);
    quad.b = static_cast<float>(b);
    quad.c = static_cast<float>(c);
    // Error budget of the plane as the shader evaluates it (float32, a few operations, each
    // within 2^-24 relative of its operands' magnitudes), of rounding a, b, c to float, and of
    // the double computation above (relative 1e-10 at most, given the area test): 5e-7 is
    // about 8 ulps of the largest term; 1e-6 absolute covers the rest.
    const double magnitude = std::abs(a) * (view.width + 2.0) + std::abs(b) * (view.height + 2.0) + std::abs(c) + 1.0;
    quad.margin = float32_above(1e-6 + 5e-7 * magnitude);
    return quad;
}

bool quad_covers(const TriangleQuad& quad, double px, double py) {
    if (px < quad.x0 || px > quad.x1 || py < quad.y0 || py > quad.y1) return false;
    for (const auto& e : quad.edges) {
        const double distance = double{e[0]} * px + double{e[1]} * py + double{e[2]};
        if (distance > 0.5 * (std::abs(double{e[0]}) + std::abs(double{e[1]})) + quad.edge_margin) return false;
    }
    return true;
}

double quad_depth_bound(const TriangleQuad& quad, double px, double py, bool max) {
    const double plane = double{quad.a} * px + double{quad.b} * py + double{quad.c};
    const double spread = 0.5 * (std::abs(double{quad.a}) + std::abs(double{quad.b})) + quad.margin;
    return max ? std::min(plane + spread, double{quad.zhi}) : std::max(plane - spread, double{quad.zlo});
}

}  // namespace collidescope::gpucull
