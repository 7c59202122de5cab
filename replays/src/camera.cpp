// The replayer's camera (look-at + perspective) and the frame layout.

#include "collidescope/replays/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collidescope::replays {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec normalized(const Vec& a) {
    const double length = std::sqrt(dot(a, a));
    return length > 0 ? Vec{a[0] / length, a[1] / length, a[2] / length} : Vec{0, 0, 1};
}

// Column-major 4x4: element (row, col) at [col * 4 + row].
using Mat = std::array<double, 16>;

Mat multiply(const Mat& a, const Mat& b) {
    Mat c{};
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[col * 4 + k];
            c[col * 4 + row] = sum;
        }
    }
    return c;
}

// An axis not parallel to `direction`, for a look-at whose up would be.
Vec up_not_along(const Vec& direction, const Vec& up) {
    if (std::abs(dot(normalized(direction), normalized(up))) <= 0.999) return up;
    return std::abs(direction[1]) < 0.9 ? Vec{0, 1, 0} : Vec{1, 0, 0};
}

Mat look_at(const Vec& eye, const Vec& target, Vec up) {
    const Vec f = normalized(sub(target, eye));
    up = up_not_along(f, up);  // looking straight along the up axis
    const Vec s = normalized(cross(f, up));
    const Vec u = cross(s, f);
    return {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
            -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

Mat perspective(double fov_degrees, double aspect, double near_plane, double far_plane) {
    const double f = 1.0 / std::tan(fov_degrees * std::numbers::pi / 360.0);
    Mat m{};
    m[0] = f / aspect;
    m[5] = f;
    m[10] = (far_plane + near_plane) / (near_plane - far_plane);
    m[11] = -1;
    m[14] = 2 * far_plane * near_plane / (near_plane - far_plane);
    return m;
}

Mat view_projection_of(const Camera& camera) {
    const double aspect = camera.viewport.h > 0 ? double(camera.viewport.w) / camera.viewport.h : 1.0;
    return multiply(perspective(camera.fov_degrees, aspect, camera.near_plane, camera.far_plane),
                    look_at(camera.eye, camera.target, camera.up));
}

// The direction the automatic camera looks from, in a z-up frame: above, in front and to the
// right, so sheets in the xy plane and objects side by side along x both show.
constexpr Vec k_auto_direction = {0.55, -0.75, 0.45};

// A z-up direction in a world whose up axis is `up`, by a proper rotation that takes z to the
// up axis: y up (glTF): x stays, the z-up frame's front (-y) becomes +z, so the camera looks
// from +z as glTF's viewers do; x up: the axes turn cyclically (x, y, z) -> (y, z, x).
Vec to_world(const Vec& v, char up) {
    if (up == 'y') return {v[0], v[2], -v[1]};
    if (up == 'x') return {v[2], v[0], v[1]};
    return v;
}

Vec up_vector(char up) { return to_world({0, 0, 1}, up); }

// The distance along `direction` from `center` at which every corner of `bounds` lies inside
// the field of view (tan_half_fov vertically, times aspect horizontally), with a small margin.
double fit_corners(const Bounds& bounds, const Vec& center, const Vec& direction, const Vec& world_up,
                   double tan_half_fov, double aspect) {
    const Vec up = up_not_along(direction, world_up);
    const Vec s = normalized(cross(Vec{-direction[0], -direction[1], -direction[2]}, up));
    const Vec u = cross(s, Vec{-direction[0], -direction[1], -direction[2]});
    double needed = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec c = {(corner & 1) != 0 ? bounds.max[0] : bounds.min[0], (corner & 2) != 0 ? bounds.max[1] : bounds.min[1],
                       (corner & 4) != 0 ? bounds.max[2] : bounds.min[2]};
        const Vec r = sub(c, center);
        const double toward = dot(r, direction);  // how much nearer the eye than the centre
        needed = std::max(needed, toward + std::abs(dot(r, s)) / (tan_half_fov * aspect));
        needed = std::max(needed, toward + std::abs(dot(r, u)) / tan_half_fov);
    }
    return needed * 1.04 + 1e-9;
}

// --camera focus: `camera` looks along `direction` (from the eye, reversed) at the focus
// region's sphere, fitted to `fit` (the tangent of the narrower half field of view). The near
// plane sits just in front of the region (what is nearer would hide the collisions), the far
// plane behind the whole scene (`scene_center`, `scene_radius`).
void frame_focus(Camera& camera, const Framing& focus, const Vec& direction, double fit, const Vec& scene_center,
                 double scene_radius) {
    const Vec d = normalized(direction);
    const double distance = focus.radius / std::sin(std::atan(fit)) * 1.02;
    camera.target = focus.center;
    camera.eye = {focus.center[0] + d[0] * distance, focus.center[1] + d[1] * distance, focus.center[2] + d[2] * distance};
    const double offset = std::sqrt(dot(sub(focus.center, scene_center), sub(focus.center, scene_center)));
    camera.far_plane = distance + offset + 2 * scene_radius + 1e-6;
    camera.near_plane = std::max(camera.far_plane * 1e-5, distance - 1.5 * focus.radius);
}

}  // namespace

void Bounds::add(double x, double y, double z) {
    const Vec p = {x, y, z};
    // Whether it was empty before this point: empty() looks at x alone, which the loop sets first.
    const bool was_empty = empty();
    for (int i = 0; i < 3; ++i) {
        min[i] = was_empty ? p[i] : std::min(min[i], p[i]);
        max[i] = was_empty ? p[i] : std::max(max[i], p[i]);
    }
}

void Bounds::add(const Bounds& other) {
    if (other.empty()) return;
    add(other.min[0], other.min[1], other.min[2]);
    add(other.max[0], other.max[1], other.max[2]);
}

FrameLayout frame_layout(int width, int height, unsigned layers) {
    FrameLayout layout;
    int top = 0;
    int bottom = height;
    int left = 0;
    int right = width;
    if ((layers & k_layer_timeline) != 0) {
        const int h = std::clamp(height / 9, 24, 96);
        layout.timeline = {0, height - h, width, h};
        bottom -= h;
    }
    if ((layers & k_layer_overlay) != 0) {
        const int w = std::clamp(width * 27 / 100, 120, 420);
        layout.panel = {0, 0, w, bottom};
        left += w;
    }
    if ((layers & k_layer_depth) != 0) {
        const int w = std::clamp(width * 17 / 100, 80, 260);
        layout.depth = {width - w, 0, w, bottom};
        right -= w;
    }
    if ((layers & k_layer_legend) != 0) {
        const int h = std::clamp(height / 24, 18, 30);
        layout.legend = {left, 0, right - left, h};
        top += h;
    }
    layout.scene = {left, top, std::max(right - left, 1), std::max(bottom - top, 1)};
    return layout;
}

std::array<float, 16> Camera::view_projection() const {
    const Mat m = view_projection_of(*this);
    std::array<float, 16> out{};
    for (int i = 0; i < 16; ++i) out[i] = float(m[i]);
    return out;
}

std::array<double, 3> Camera::project(double x, double y, double z) const {
    const Mat m = view_projection_of(*this);
    std::array<double, 4> clip{};
    for (int row = 0; row < 4; ++row) clip[row] = m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row];
    const double ndc_x = clip[0] / clip[3];
    const double ndc_y = clip[1] / clip[3];
    return {viewport.x + (ndc_x + 1) * 0.5 * viewport.w, viewport.y + (1 - ndc_y) * 0.5 * viewport.h,
            clip[2] / clip[3]};
}

Camera make_camera(const CameraSpec& spec, const Bounds& bounds, const Rect& viewport, std::uint64_t ordinal,
                   std::uint64_t frames, const Framing* focus) {
    Camera camera;
    camera.viewport = viewport;
    camera.fov_degrees = spec.fov_degrees;
    camera.up = up_vector(spec.up);
    Vec center = {0, 0, 0};
    double radius = 1;
    if (!bounds.empty()) {
        for (int i = 0; i < 3; ++i) center[i] = 0.5 * (bounds.min[i] + bounds.max[i]);
        radius = 0.5 * std::sqrt(dot(sub(bounds.max, bounds.min), sub(bounds.max, bounds.min)));
        if (radius <= 0) radius = 1;
    }
    const double aspect = viewport.h > 0 ? double(viewport.w) / viewport.h : 1.0;
    const double half_fov = spec.fov_degrees * std::numbers::pi / 360.0;
    // Distance at which the bounding sphere fits the narrower of the two fields of view.
    const double fit = std::min(std::tan(half_fov), std::tan(half_fov) * aspect);
    const double distance = radius / std::sin(std::atan(fit)) * 1.02;
    if ((spec.kind == CameraSpec::Kind::Focus || spec.kind == CameraSpec::Kind::Region) && focus != nullptr) {
        frame_focus(camera, *focus, to_world(k_auto_direction, spec.up), fit, center, radius);
        return camera;
    }
    if (spec.kind == CameraSpec::Kind::Fixed) {
        camera.eye = spec.eye;
        camera.target = spec.target_given ? spec.target : center;
    } else {
        Vec direction = normalized(k_auto_direction);
        if (spec.kind == CameraSpec::Kind::Orbit) {
            // About the up axis: z in the z-up frame, mapped with the rest.
            const double step = spec.degrees_per_frame != 0 ? spec.degrees_per_frame
                                                            : 360.0 / double(std::max<std::uint64_t>(frames, 1));
            const double angle = step * double(ordinal) * std::numbers::pi / 180.0;
            direction = {direction[0] * std::cos(angle) - direction[1] * std::sin(angle),
                         direction[0] * std::sin(angle) + direction[1] * std::cos(angle), direction[2]};
        }
        direction = to_world(direction, spec.up);
        double eye_distance = distance;
        if (spec.kind != CameraSpec::Kind::Orbit && !bounds.empty()) {
            // A fixed direction: fit the box's eight corners rather than its sphere (closer).
            eye_distance = fit_corners(bounds, center, direction, camera.up, std::tan(half_fov), aspect);
        }
        camera.target = center;
        camera.eye = {center[0] + direction[0] * eye_distance, center[1] + direction[1] * eye_distance,
                      center[2] + direction[2] * eye_distance};
    }
    const double eye_distance = std::sqrt(dot(sub(camera.eye, camera.target), sub(camera.eye, camera.target)));
    camera.far_plane = eye_distance + 2 * radius + 1e-6;
    camera.near_plane = std::max(camera.far_plane * 1e-4, eye_distance - 2 * radius);
    if (camera.near_plane <= 0) camera.near_plane = camera.far_plane * 1e-4;
    return camera;
}

}  // namespace collidescope::replays
