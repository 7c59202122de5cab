// The interval's input checks and its default tolerance.

#include "ccd/interval_checks.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace collidescope::ccd {
namespace {

void check_finite(const Frame& frame) {
    for (std::size_t i = 0; i < frame.objects.size(); ++i) {
        const auto vertices = frame.objects[i].vertices.span();
        for (std::size_t v = 0; v < vertices.size(); ++v) {
            if (!vertices[v].allFinite()) {
                throw InputError("frame " + std::to_string(frame.index) + ", object " + std::to_string(i) + ": vertex " +
                                 std::to_string(v) + " is not finite (between-frames detection needs finite coordinates)");
            }
            // Products of three coordinate differences must not overflow (the filters' bounds).
            if (vertices[v].cwiseAbs().maxCoeff() > 1e100) {
                throw InputError("frame " + std::to_string(frame.index) + ", object " + std::to_string(i) + ": vertex " +
                                 std::to_string(v) + " has a coordinate above 1e100 (between-frames detection's limit)");
            }
        }
    }
}

}  // namespace

void check_interval(const Frame& from, const Frame& to) {
    if (from.objects.size() != to.objects.size()) {
        throw InputError("frames " + std::to_string(from.index) + " and " + std::to_string(to.index) + " have " +
                         std::to_string(from.objects.size()) + " and " + std::to_string(to.objects.size()) +
                         " objects: between-frames detection needs the same objects in both");
    }
    for (std::size_t i = 0; i < from.objects.size(); ++i) {
        const Topology& a = *from.objects[i].topology;
        const Topology& b = *to.objects[i].topology;
        const bool same = &a == &b || (a.revision != 0 && a.revision == b.revision) ||
                          (a.vertex_count == b.vertex_count && a.triangles == b.triangles);
        if (!same) {
            throw InputError("object " + std::to_string(i) + " changes its mesh between frames " + std::to_string(from.index) +
                             " and " + std::to_string(to.index) + " (" + std::to_string(a.vertex_count) + " to " +
                             std::to_string(b.vertex_count) + " vertices, " + std::to_string(a.triangles.size()) + " to " +
                             std::to_string(b.triangles.size()) +
                             " triangles): between-frames detection needs the same topology at both ends");
        }
    }
    check_finite(from);
    check_finite(to);
}

double interval_tolerance(const Frame& from, const Frame& to, double requested) {
    if (requested > 0) return requested;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Frame* frame : {&from, &to}) {
        for (const ObjectFrame& object : frame->objects) {
            for (const Vec3& v : object.vertices.span()) {
                lo = lo.cwiseMin(v);
                hi = hi.cwiseMax(v);
            }
        }
    }
    const double extent = lo.allFinite() ? (hi - lo).maxCoeff() : 0.0;
    return 1e-6 * (extent > 0 ? extent : 1.0);
}

}  // namespace collidescope::ccd

namespace collidescope {

std::string with_object_names(const std::string& message, const std::vector<std::string>& names) {
    // A plain scan, not std::regex: GCC 12's <regex> warns (maybe-uninitialized) under the
    // sanitizers and costs the engine its compile time.
    const std::string word = "object ";
    std::string out;
    std::size_t at = 0;
    for (std::size_t found = message.find(word); found != std::string::npos; found = message.find(word, at)) {
        std::size_t end = found + word.size();
        while (end < message.size() && message[end] >= '0' && message[end] <= '9') ++end;
        out += message.substr(at, end - at);
        at = end;
        if (end == found + word.size() || end - found - word.size() > 9) continue;  // no index, or far too long for one
        const std::size_t index = std::stoul(message.substr(found + word.size(), end - found - word.size()));
        if (index < names.size()) out += " ('" + names[index] + "')";
    }
    return out + message.substr(at);
}

}  // namespace collidescope
