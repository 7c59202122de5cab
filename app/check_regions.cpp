// The regions sink of `collidescope check`.

#include "check_regions.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>

namespace collidescope::app {
namespace {

nlohmann::ordered_json point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

std::string name_of(const std::vector<std::string>& names, std::uint32_t object) {
    return object < names.size() ? names[object] : "object" + std::to_string(object);
}

}  // namespace

std::string region_json(std::uint32_t frame, const Region& region, const std::vector<std::string>& names) {
    nlohmann::ordered_json curves = nlohmann::ordered_json::array();
    for (const IntersectionCurve& curve : region.curves) {
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (const Vec3& p : curve.points) points.push_back(point(p));
        curves.push_back({{"closed", curve.closed}, {"length", curve.length}, {"points", std::move(points)}});
    }
    const nlohmann::ordered_json object = {
        {"frame", frame},
        {"region", region.id},
        {"objects", {region.obj_a, region.obj_b}},
        {"names", {name_of(names, region.obj_a), name_of(names, region.obj_b)}},
        {"pairs", region.pairs},
        {"triangles", {region.triangles_a.size(), region.triangles_b.size()}},
        {"loops", region.loops},
        {"curve_length", region.curve_length},
        {"coplanar_area", region.coplanar_area},
        {"box", {point(region.box.min()), point(region.box.max())}},
        {"predecessors", region.predecessors},
        {"curves", std::move(curves)},
    };
    return object.dump();
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
        if (track.split_from != 0) line += "; split from region " + std::to_string(track.split_from);
        if (track.merged_into != 0) line += "; merged into region " + std::to_string(track.merged_into);
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace collidescope::app
