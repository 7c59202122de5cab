// Regions over time: each region is matched to last frame's regions of the same objects by the
// colliding triangles they share (or, sharing none, by overlapping boxes), then ids pass along
// the strongest matches; what is left over splits off or merges, and says so.

#include "collidescope/regions.hpp"

#include <algorithm>
#include <map>

namespace collidescope {
namespace {

std::size_t shared(const std::vector<std::uint32_t>& x, const std::vector<std::uint32_t>& y) {
    std::size_t count = 0;
    for (auto i = x.begin(), j = y.begin(); i != x.end() && j != y.end();) {
        if (*i < *j) {
            ++i;
        } else if (*j < *i) {
            ++j;
        } else {
            ++count, ++i, ++j;
        }
    }
    return count;
}

}  // namespace

void RegionTracker::update(std::uint32_t frame, std::vector<Region>& regions) {
    if (m_any && frame != m_last_frame + 1) m_previous.clear();  // a gap: nothing continues

    // weight[r][p]: triangles shared (+1, so a box overlap alone weighs 1 and sharing wins).
    std::vector<std::map<std::size_t, std::size_t>> weight(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
        bool any_shared = false;
        for (std::size_t p = 0; p < m_previous.size(); ++p) {
            const Previous& previous = m_previous[p];
            if (previous.obj_a != regions[r].obj_a || previous.obj_b != regions[r].obj_b) continue;
            const std::size_t n = shared(regions[r].triangles_a, previous.triangles_a) +
                                  shared(regions[r].triangles_b, previous.triangles_b);
            if (n > 0) {
                weight[r][p] = n + 1;
                any_shared = true;
            }
        }
        if (any_shared) continue;
        for (std::size_t p = 0; p < m_previous.size(); ++p) {
            const Previous& previous = m_previous[p];
            if (previous.obj_a == regions[r].obj_a && previous.obj_b == regions[r].obj_b &&
                previous.box.intersects(regions[r].box)) {
                weight[r][p] = 1;
            }
        }
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
        for (const auto& [p, w] : weight[r]) {
            region.predecessors.push_back(m_previous[p].id);
            if (w > strongest_weight) strongest_weight = w, strongest = p;
            if (best_successor[p] == r && w > keeper_weight) keeper_weight = w, keeper = p;
        }
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
    }
    // Previous regions that passed their id to nobody but have a successor merged into it.
    for (std::size_t p = 0; p < m_previous.size(); ++p) {
        if (best_successor[p] == SIZE_MAX) continue;
        const Region& successor = regions[best_successor[p]];
        if (successor.id != m_previous[p].id) m_tracks[m_previous[p].id - 1].merged_into = successor.id;
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
