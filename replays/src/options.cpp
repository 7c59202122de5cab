// Parsing the replayer's option strings: --show, --camera, --sheet-frames.

#include "collidescope/replays/options.hpp"

#include "collidescope/error.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace collidescope::replays {
namespace {

const std::pair<const char*, Layer> k_layer_names[] = {
    {"meshes", k_layer_meshes},   {"collisions", k_layer_collisions}, {"pcs", k_layer_pcs},
    {"depth", k_layer_depth},     {"overlay", k_layer_overlay},       {"timeline", k_layer_timeline},
    {"legend", k_layer_legend},   {"regions", k_layer_regions},
};

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

bool parse_double(const std::string& text, double& value) {
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    return !text.empty() && result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

bool parse_point(const std::string& text, std::array<double, 3>& point) {
    const std::vector<std::string> parts = split(text, ',');
    if (parts.size() != 3) return false;
    for (std::size_t i = 0; i < 3; ++i) {
        if (!parse_double(parts[i], point[i])) return false;
    }
    return true;
}

}  // namespace

unsigned parse_layers(const std::string& list) {
    if (list == "all") return k_layer_all;
    if (list == "none" || list.empty()) return 0;
    unsigned layers = 0;
    for (const std::string& name : split(list, ',')) {
        bool known = false;
        for (const auto& [layer_name, layer] : k_layer_names) {
            if (name == layer_name) {
                layers |= layer;
                known = true;
            }
        }
        if (!known) {
            throw InputError("--show: unknown layer '" + name +
                             "' (layers: meshes, collisions, pcs, depth, overlay, timeline, legend, regions; or all, none)");
        }
    }
    return layers;
}

CameraSpec parse_camera(const std::string& spec) {
    CameraSpec camera;
    const std::string usage =
        "--camera must be auto, orbit, orbit:DEGREES_PER_FRAME, focus, region:ID or fixed:EX,EY,EZ[:TX,TY,TZ], not '" +
        spec + "'";
    if (spec == "auto") return camera;
    if (spec == "focus") {
        camera.kind = CameraSpec::Kind::Focus;
        return camera;
    }
    if (spec == "orbit") {
        camera.kind = CameraSpec::Kind::Orbit;
        return camera;
    }
    const std::vector<std::string> parts = split(spec, ':');
    if (parts.size() == 2 && parts[0] == "orbit") {
        camera.kind = CameraSpec::Kind::Orbit;
        if (!parse_double(parts[1], camera.degrees_per_frame)) throw InputError(usage);
        return camera;
    }
    if (parts.size() == 2 && parts[0] == "region") {
        camera.kind = CameraSpec::Kind::Region;
        double id = 0;
        if (!parse_double(parts[1], id) || id < 1 || id != std::floor(id) || id > 4294967295.0) {
            throw InputError(usage + ": a region id is a whole number from 1 (check --regions or inspect lists them)");
        }
        camera.region = static_cast<std::uint32_t>(id);
        return camera;
    }
    if ((parts.size() == 2 || parts.size() == 3) && parts[0] == "fixed") {
        camera.kind = CameraSpec::Kind::Fixed;
        if (!parse_point(parts[1], camera.eye)) throw InputError(usage);
        if (parts.size() == 3) {
            if (!parse_point(parts[2], camera.target)) throw InputError(usage);
            camera.target_given = true;
        }
        if (camera.target_given && camera.eye == camera.target) throw InputError(usage + ": eye equals target");
        return camera;
    }
    throw InputError(usage);
}

char parse_up_axis(const std::string& text) {
    if (text == "x" || text == "y" || text == "z") return text[0];
    throw InputError("--up must be x, y or z, not '" + text + "'");
}

}  // namespace collidescope::replays
