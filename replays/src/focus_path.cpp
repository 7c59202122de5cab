// focus_path(): where `--camera focus` looks in each frame (docs/how-to/replay.md, "Camera").

#include "collidescope/replays/camera.hpp"

#include <algorithm>
#include <cmath>

namespace collidescope::replays {
namespace {

Framing framing_of(const Bounds& box) {
    Framing framing;
    double squared = 0;
    for (int i = 0; i < 3; ++i) {
        framing.center[i] = 0.5 * (box.min[i] + box.max[i]);
        squared += (box.max[i] - box.min[i]) * (box.max[i] - box.min[i]);
    }
    framing.radius = 0.5 * std::sqrt(squared);
    return framing;
}

// Centre and log radius, the quantities smoothed (a log radius zooms at a steady rate).
struct Aim {
    std::array<double, 3> center;
    double log_radius;
};

// Where each frame would look without smoothing.
std::vector<Aim> aims(const std::vector<Bounds>& colliding, const Framing& whole, const FocusSettings& settings) {
    const double min_radius = std::max(whole.radius * settings.min_fraction, 1e-12);
    const Aim scene{whole.center, std::log(std::max(whole.radius, min_radius))};
    std::vector<Aim> out;
    Aim last = scene;
    std::uint32_t since_collision = settings.hold_frames + 1;
    for (const Bounds& box : colliding) {
        if (!box.empty()) {
            const Framing region = framing_of(box);
            last = {region.center, std::log(std::max(region.radius * settings.padding, min_radius))};
            since_collision = 0;
        } else {
            ++since_collision;
        }
        out.push_back(since_collision <= settings.hold_frames ? last : scene);
    }
    return out;
}

void blend(Aim& into, const Aim& toward, double s) {
    for (int i = 0; i < 3; ++i) into.center[i] += s * (toward.center[i] - into.center[i]);
    into.log_radius += s * (toward.log_radius - into.log_radius);
}

}  // namespace

std::vector<Framing> focus_path(const std::vector<Bounds>& colliding, const Bounds& whole, const FocusSettings& settings) {
    const Framing scene = whole.empty() ? Framing{} : framing_of(whole);
    std::vector<Aim> path = aims(colliding, scene, settings);
    const double s = std::clamp(settings.smoothing, 1e-3, 1.0);
    // Forward, then backward over the result: the second pass undoes the first one's lag, so
    // the camera arrives at a collision as it happens rather than after.
    for (std::size_t k = 1; k < path.size(); ++k) blend(path[k], path[k - 1], 1 - s);
    for (std::size_t k = path.size(); k-- > 1;) blend(path[k - 1], path[k], 1 - s);
    std::vector<Framing> out;
    for (const Aim& aim : path) out.push_back({aim.center, std::exp(aim.log_radius)});
    return out;
}

}  // namespace collidescope::replays
