// Regions over time: each region is matched to last frame's regions of the same objects by the
// colliding triangles they share (or, sharing none, by overlapping boxes), then ids pass along
// the strongest matches; what is left over splits off or merges, and says so.

#include "collidescope/regions.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace collidescope {
namespace {

// Orders (objects, low x) entries by their objects alone, against an object pair's key.
struct ByObjects {
    bool operator()(const std::pair<std::pair<std::uint64_t, double>, std::size_t>& entry, std::uint64_t key) const {
        return entry.first.first < key;
    }
    bool operator()(std::uint64_t key, const std::pair<std::pair<std::uint64_t, double>, std::size_t>& entry) const {
        return key < entry.first.first;
    }
};

}  // namespace

void RegionTracker::update(std::uint32_t frame, std::vector<Region>& regions) {
    if (m_any && frame != m_last_frame + 1) m_previous.clear();  // a gap: nothing continues

    // Last frame's triangles, each with its region: per (objects, side), an array over the
    // triangles, kept from frame to frame; an entry is current when it carries this stamp.
    const auto objects_of = [](std::uint32_t a, std::uint32_t b) { return std::uint64_t(a) << 32 | b; };
    if (++m_stamp == 0) {
        for (auto& [key, index] : m_owners) std::fill(index.stamp.begin(), index.stamp.end(), 0);
        m_stamp = 1;
    }
    for (std::size_t p = 0; p < m_previous.size(); ++p) {
        const Previous& previous = m_previous[p];
        for (const std::uint32_t side : {0u, 1u}) {
            OwnerIndex& index = m_owners[{objects_of(previous.obj_a, previous.obj_b), side}];
            for (const std::uint32_t t : side == 0 ? previous.triangles_a : previous.triangles_b) {
                if (t >= index.stamp.size()) {
                    index.stamp.resize(t + 1 + t / 2, 0);
                    index.previous.resize(index.stamp.size(), 0);
                }
                index.stamp[t] = m_stamp;
                index.previous[t] = static_cast<std::uint32_t>(p);
            }
        }
    }
    // Last frame's boxes by (objects, low x), and within each object pair the highest high x so
    // far: the boxes before the first whose running highest reaches a box's low x all end
    // before it. Scanning from the object pair's first box instead made matching by boxes
    // quadratic in the regions (data set E: 500 one-pair regions a frame, a quarter of the
    // regions' time).
    std::vector<std::pair<std::pair<std::uint64_t, double>, std::size_t>> by_box;  // ((objects, box min x), previous)
    for (std::size_t p = 0; p < m_previous.size(); ++p) {
        by_box.push_back({{objects_of(m_previous[p].obj_a, m_previous[p].obj_b), m_previous[p].box.min().x()}, p});
    }
    std::sort(by_box.begin(), by_box.end());
    std::vector<double> highest(by_box.size());
    for (std::size_t k = 0; k < by_box.size(); ++k) {
        const double high = m_previous[by_box[k].second].box.max().x();
        const bool first = k == 0 || by_box[k - 1].first.first != by_box[k].first.first;
        highest[k] = first ? high : std::max(highest[k - 1], high);
    }

    // weight[r]: (p, triangles shared + 1), by p: a box overlap alone weighs 1, so sharing wins.
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> weight(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
        const std::uint64_t objects = objects_of(regions[r].obj_a, regions[r].obj_b);
        std::vector<std::pair<std::size_t, std::size_t>>& w = weight[r];
        for (const std::uint32_t side : {0u, 1u}) {
            const auto found = m_owners.find({objects, side});
            if (found == m_owners.end()) continue;
            const OwnerIndex& index = found->second;
            for (const std::uint32_t t : side == 0 ? regions[r].triangles_a : regions[r].triangles_b) {
                if (t >= index.stamp.size() || index.stamp[t] != m_stamp) continue;
                const std::size_t p = index.previous[t];
                auto hit = !w.empty() && w.back().first == p ? w.end() - 1 : std::find_if(w.begin(), w.end(), [&](const auto& e) { return e.first == p; });
                if (hit == w.end()) {
                    w.emplace_back(p, 2);
                } else {
                    ++hit->second;
                }
            }
        }
        std::sort(w.begin(), w.end());
        const bool any_shared = !w.empty();
        if (any_shared) continue;
        // Boxes: last frame's regions of the same objects, by the low x of their boxes, from the
        // first that can reach this box's low x.
        const auto block = std::equal_range(by_box.begin(), by_box.end(), objects, ByObjects{});
        const auto begin = static_cast<std::size_t>(block.first - by_box.begin());
        const auto end = static_cast<std::size_t>(block.second - by_box.begin());
        const double low = regions[r].box.min().x();
        std::size_t k = static_cast<std::size_t>(
            std::partition_point(highest.begin() + static_cast<std::ptrdiff_t>(begin),
                                 highest.begin() + static_cast<std::ptrdiff_t>(end), [&](double h) { return h < low; }) -
            highest.begin());
        for (; k < end; ++k) {
            if (by_box[k].first.second > regions[r].box.max().x()) break;
            if (m_previous[by_box[k].second].box.intersects(regions[r].box)) weight[r].emplace_back(by_box[k].second, 1);
        }
        std::sort(weight[r].begin(), weight[r].end());
    }
    // Each previous region's strongest successor; each region's strongest predecessor among
    // those whose strongest successor it is.
    std::vector<std::size_t> best_successor(m_previous.size(), SIZE_MAX), best_weight(m_previous.size(), 0);
    for (std::size_t r = 0; r < regions.size(); ++r) {
        for (const auto& [p, w] : weight[r]) {
            if (w > best_weight[p]) best_weight[p] = w, best_successor[p] = r;
        }
    }
    for (std::size_t r = 0; r < regions.size(); ++r) {
        Region& region = regions[r];
        region.predecessors.clear();
        std::size_t keeper = SIZE_MAX, keeper_weight = 0, strongest = SIZE_MAX, strongest_weight = 0;
        std::vector<std::pair<std::size_t, std::size_t>> by_weight;  // (weight, previous), strongest first
        for (const auto& [p, w] : weight[r]) {
            by_weight.emplace_back(w, p);
            if (w > strongest_weight) strongest_weight = w, strongest = p;
            if (best_successor[p] == r && w > keeper_weight) keeper_weight = w, keeper = p;
        }
        std::stable_sort(by_weight.begin(), by_weight.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
        for (const auto& [w, p] : by_weight) region.predecessors.push_back(m_previous[p].id);
        if (keeper != SIZE_MAX) {
            region.id = m_previous[keeper].id;
        } else {
            region.id = static_cast<std::uint32_t>(m_tracks.size() + 1);
            RegionTrack track;
            track.id = region.id;
            track.obj_a = region.obj_a;
            track.obj_b = region.obj_b;
            track.first_frame = frame;
            track.split_from = strongest != SIZE_MAX ? m_previous[strongest].id : 0;
            m_tracks.push_back(track);
        }
        RegionTrack& track = m_tracks[region.id - 1];
        track.last_frame = frame;
        ++track.frames;
        track.max_pairs = std::max(track.max_pairs, region.pairs);
        if (region.curve_length > track.max_curve_length || track.frames == 1) {
            track.max_curve_length = region.curve_length;
            track.max_curve_length_frame = frame;
        }
        if (region.depth > track.max_depth || (std::isnan(track.max_depth) && !std::isnan(region.depth))) {
            track.max_depth = region.depth;
            track.max_depth_frame = frame;
        }
    }
    // A previous region whose id goes on nowhere, but which a region continues, merged into the
    // first such region (frame order; a reader of the recording can tell the same from the
    // predecessors alone).
    for (const Region& region : regions) {
        for (const std::uint32_t id : region.predecessors) {
            RegionTrack& ended = m_tracks[id - 1];
            if (id != region.id && ended.last_frame != frame && ended.merged_into == 0) ended.merged_into = region.id;
        }
    }
    m_previous.clear();
    for (std::size_t r = 0; r < regions.size(); ++r) {
        m_previous.push_back({regions[r].id, regions[r].obj_a, regions[r].obj_b, regions[r].box, regions[r].triangles_a,
                              regions[r].triangles_b});
    }
    m_last_frame = frame;
    m_any = true;
}

}  // namespace collidescope
