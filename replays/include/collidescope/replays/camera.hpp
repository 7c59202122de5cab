#pragma once
/// The replayer's camera and frame layout: where the meshes land in an image (public so the
/// tests can find a triangle's pixels in a PNG).

#include "collidescope/replays/options.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace collidescope::replays {

/// An axis-aligned box, input length units.
struct Bounds {
    std::array<double, 3> min{1, 1, 1};
    std::array<double, 3> max{-1, -1, -1};  ///< min > max: empty
    bool empty() const { return min[0] > max[0]; }
    void add(double x, double y, double z);
    void add(const Bounds& other);
};

/// A rectangle of an image, pixels, origin at the top left (PNG row order).
struct Rect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
    bool contains(double px, double py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

/// Where each layer goes in a width x height frame: the panel on the left, the depth thumbnails
/// on the right, the timeline along the bottom, the legend across the top of the scene, the
/// meshes in what is left. Layers that are off take no room.
struct FrameLayout {
    Rect scene;
    Rect panel;     ///< k_layer_overlay
    Rect depth;     ///< k_layer_depth
    Rect timeline;  ///< k_layer_timeline
    Rect legend;    ///< k_layer_legend
};

FrameLayout frame_layout(int width, int height, unsigned layers);

/// A perspective camera looking into a viewport of an image.
struct Camera {
    std::array<double, 3> eye{};
    std::array<double, 3> target{};
    std::array<double, 3> up{0, 0, 1};
    double fov_degrees = 40;
    double near_plane = 0.01;
    double far_plane = 100;
    Rect viewport;  ///< where the scene is drawn in the image
    /// Projection times view, column-major (OpenGL's layout).
    std::array<float, 16> view_projection() const;
    /// Image pixel coordinates (x right, y down, from the image's top left) of a world point,
    /// and its depth in [-1, 1] (NDC z).
    std::array<double, 3> project(double x, double y, double z) const;
};

/// A sphere the camera keeps in view: centre and radius, input length units.
struct Framing {
    std::array<double, 3> center{};
    double radius = 1;
};

/// How `--camera focus` follows the collisions (focus_path).
struct FocusSettings {
    double padding = 1.6;         ///< the framed radius over the colliding triangles' half diagonal
    double min_fraction = 0.06;   ///< smallest framed radius, as a fraction of the whole scene's
    std::uint32_t hold_frames = 12;  ///< frames without collisions that keep the last region
    double smoothing = 0.2;       ///< exponential smoothing factor per frame (0 < s <= 1; 1 = none)
};

/// The region `--camera focus` frames in each replayed frame: `colliding[k]` is the box of
/// frame k's colliding triangles (empty: none), `whole` the box of every replayed frame. A
/// frame with collisions aims at their box, padded and at least a minimum size; a frame
/// without keeps the last region for `hold_frames`, then eases back to the whole scene. The
/// aims are smoothed forward and then backward (exponentially, so the camera neither lags
/// nor jumps): from one frame to the next, the centre and the log radius each move by at most
/// `smoothing` times the largest distance between two frames' aims.
std::vector<Framing> focus_path(const std::vector<Bounds>& colliding, const Bounds& whole,
                                const FocusSettings& settings = {});

/// The camera of replayed frame number `ordinal` (0 = the first replayed frame) of `frames`,
/// framing `bounds` into `viewport` according to `spec`, with spec.up up on screen. Auto and
/// Fixed give the same camera for every frame; Orbit turns by spec.degrees_per_frame per frame
/// (or one turn in all) about the up axis; Focus frames `focus` (this frame's entry of
/// focus_path; nullptr: as Auto), with the near plane just in front of it, so nothing between
/// the eye and the collisions hides them.
Camera make_camera(const CameraSpec& spec, const Bounds& bounds, const Rect& viewport, std::uint64_t ordinal,
                   std::uint64_t frames, const Framing* focus = nullptr);

}  // namespace collidescope::replays
