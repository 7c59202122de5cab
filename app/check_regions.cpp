// The regions sink of `collidescope check`.

#include "check_regions.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace collidescope::app {
namespace {

std::string name_of(const std::vector<std::string>& names, std::uint32_t object) {
    return object < names.size() ? names[object] : "object" + std::to_string(object);
}

// JSON by hand: a region line holds every point of its curves, and building it as a JSON value
// cost more than finding the regions. Numbers are the shortest text that reads back exactly.
void number(std::string& out, double value) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out.append(text, result.ptr);
    // JSON readers take "1e-05" and "3"; nlohmann wrote 3.0 for a double, so keep a point.
    if (std::string_view(text, static_cast<std::size_t>(result.ptr - text)).find_first_of(".eE") == std::string_view::npos) {
        out += ".0";
    }
}

void number(std::string& out, std::uint64_t value) {
    char text[24];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out.append(text, result.ptr);
}

void point(std::string& out, const Vec3& p) {
    out += '[';
    number(out, p.x());
    out += ',';
    number(out, p.y());
    out += ',';
    number(out, p.z());
    out += ']';
}

}  // namespace

std::string region_json(std::uint32_t frame, const Region& region, const std::vector<std::string>& names) {
    std::string out = "{\"frame\":";
    number(out, std::uint64_t{frame});
    out += ",\"region\":";
    number(out, std::uint64_t{region.id});
    out += ",\"objects\":[";
    number(out, std::uint64_t{region.obj_a});
    out += ',';
    number(out, std::uint64_t{region.obj_b});
    out += "],\"names\":[" + nlohmann::json(name_of(names, region.obj_a)).dump() + "," +
           nlohmann::json(name_of(names, region.obj_b)).dump() + "],\"pairs\":";
    number(out, std::uint64_t{region.pairs});
    out += ",\"triangles\":[";
    number(out, std::uint64_t{region.triangles_a.size()});
    out += ',';
    number(out, std::uint64_t{region.triangles_b.size()});
    out += "],\"loops\":";
    number(out, std::uint64_t{region.loops});
    out += ",\"curve_length\":";
    number(out, region.curve_length);
    out += ",\"coplanar_area\":";
    number(out, region.coplanar_area);
    // NaN where not defined (no closed object, or self-contact): number() writes null.
    out += ",\"inside_area\":[";
    number(out, region.inside_area_a);
    out += ',';
    number(out, region.inside_area_b);
    out += "],\"depth\":";
    number(out, region.depth);
    out += ",\"box\":[";
    point(out, region.box.min());
    out += ',';
    point(out, region.box.max());
    out += "],\"predecessors\":[";
    for (std::size_t k = 0; k < region.predecessors.size(); ++k) {
        if (k > 0) out += ',';
        number(out, std::uint64_t{region.predecessors[k]});
    }
    out += "],\"curves\":[";
    for (std::size_t c = 0; c < region.curves.size(); ++c) {
        const IntersectionCurve& curve = region.curves[c];
        out += c > 0 ? ",{\"closed\":" : "{\"closed\":";
        out += curve.closed ? "true" : "false";
        out += ",\"length\":";
        number(out, curve.length);
        out += ",\"points\":[";
        for (std::size_t k = 0; k < curve.points.size(); ++k) {
            if (k > 0) out += ',';
            point(out, curve.points[k]);
        }
        out += "]}";
    }
    out += "]}";
    return out;
}

void RegionsWriter::on_frame(const FrameReport& report) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Region> regions = find_regions(report.frame, report.colliding_pairs);
    m_tracker.update(report.stats.frame, regions);
    m_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (const Region& region : regions) m_out << region_json(report.stats.frame, region, m_names) << '\n';
}

std::vector<std::string> RegionsWriter::summary_lines() const {
    std::vector<std::string> lines;
    for (const RegionTrack& track : m_tracker.tracks()) {
        const std::string objects = track.obj_a == track.obj_b
                                        ? "object '" + name_of(m_names, track.obj_a) + "' (self)"
                                        : "objects '" + name_of(m_names, track.obj_a) + "' and '" +
                                              name_of(m_names, track.obj_b) + "'";
        char figures[160];
        std::snprintf(figures, sizeof figures, ", frames %u-%u (%u frame%s), curve %.6g at most (frame %u), %u pairs at most",
                      track.first_frame, track.last_frame, track.frames, track.frames == 1 ? "" : "s",
                      track.max_curve_length, track.max_curve_length_frame, track.max_pairs);
        std::string line = "region " + std::to_string(track.id) + ": " + objects + figures;
        if (!std::isnan(track.max_depth)) {
            std::snprintf(figures, sizeof figures, ", %.6g deep at most (frame %u)", track.max_depth, track.max_depth_frame);
            line += figures;
        }
        if (track.split_from != 0) line += "; split from region " + std::to_string(track.split_from);
        if (track.merged_into != 0) line += "; merged into region " + std::to_string(track.merged_into);
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace collidescope::app
