#pragma once
// One axis-aligned orthographic view and the conservative record of each triangle in it
// (engine/src/gpucull, private). Everything that makes the cull conservative is decided here,
// on the CPU, in double precision with outward rounding; the GPU only evaluates the bounds
// these records describe (shaders.cpp) and compares float depths exactly. docs/explanation/gpu_cull.md
// has the argument.

#include "collidescope/scene.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <span>
#include <vector>

namespace collidescope::gpucull {

/// A view along `axis` (0 = x, 1 = y, 2 = z) fitted to `bounds`: pixel coordinates (u, v) on
/// the other two axes span [0, width] x [0, height]; depth along `axis` maps to [0.25, 0.75],
/// far from the clip planes (depth clamping is on as well).
struct View {
    int axis = 2;
    Eigen::AlignedBox3d bounds;
    int width = 512;
    int height = 512;
};

/// How the GPU draws one triangle in one view. Coverage: the pixel rectangle [x0, x1] x
/// [y0, y1] (whole pixels: every pixel whose closed square touches the projected triangle's
/// box), and within it the pixels whose square is on the inner side of all three edge lines,
/// e = (nx, ny, d) with nx px + ny py + d <= (|nx| + |ny|) / 2 + edge_margin at the pixel
/// centre (px, py): with the box, a separating-axis test, so exactly the pixels the triangle
/// touches, widened by the margin. Depth: over such a pixel the triangle's depth lies within
/// plane(px, py) -/+ (|a| + |b|) / 2 -/+ margin, clamped to [zlo, zhi], plane = a px + b py + c.
/// 96 bytes, the layout the shaders read.
struct TriangleQuad {
    float x0, y0, x1, y1;  ///< pixel rectangle (integers)
    float a, b, c;         ///< depth plane in pixel coordinates
    float margin;          ///< covers double and float32 evaluation error of the plane
    float zlo, zhi;        ///< the triangle's depth range, rounded outward to float
    std::uint32_t id;      ///< index into the drawn set (flag slot)
    float edge_margin;     ///< pixels; covers the evaluation error of the edge lines
    float edges[3][3];     ///< (nx, ny, d) per edge, unit normal pointing out; zero = no test
    float pad[3] = {};
};
static_assert(sizeof(TriangleQuad) == 96);

/// The record of the triangle with corners p0, p1, p2 in `view`, with `id`.
TriangleQuad make_quad(const View& view, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       std::uint32_t id);

/// Whether the GPU draws `quad` at the pixel with centre (px, py), evaluated in double.
bool quad_covers(const TriangleQuad& quad, double px, double py);

/// Depth bounds of `quad` over the pixel with centre (px, py), evaluated in double: the
/// reference the shaders are tested against. `max` = the tested item's bound (upper),
/// otherwise the occluder's (lower).
double quad_depth_bound(const TriangleQuad& quad, double px, double py, bool max);

}  // namespace collidescope::gpucull
