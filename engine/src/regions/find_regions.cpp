// A frame's regions: every pair's intersection (in parallel), the pairs joined into regions by
// the vertices their triangles share (a union-find), then each
// region's counts, box and curves (in parallel over regions).

#include "curves.hpp"
#include "pair_intersection.hpp"
#include "penetration.hpp"
#include "stamped_marks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <utility>

namespace collidescope {
namespace {

// The pairs of each region, regions ordered by their first pair. Within the pairs of one
// object pair, a union-find over the two objects' vertices (one array for self-contact): each
// colliding triangle joins its three vertices (once), each pair joins a vertex of its triangle
// to one of the other's. Two pairs then share a set exactly when a chain of shared vertices
// connects them: one union per pair and two per colliding triangle, where joining each pair at
// its six vertices took six.
std::vector<std::vector<std::uint32_t>> group_pairs(const Frame& frame, std::span<const TrianglePair> pairs) {
    // The pairs in object-pair order (the pipeline's sorted pairs already are).
    const auto objects = [&](std::size_t i) { return std::uint64_t(pairs[i].obj_a) << 32 | pairs[i].obj_b; };
    // Working arrays as long as the pair list, kept from call to call on this thread (first-touch
    // page faults were a third of the grouping's time on a million pairs).
    thread_local std::vector<std::uint32_t> order_kept, set_kept, region_kept;
    const auto sized = [&](std::vector<std::uint32_t>& kept) {
        if (kept.size() < pairs.size()) kept.resize(pairs.size());
        return std::span<std::uint32_t>(kept.data(), pairs.size());
    };
    bool sorted = true;
    for (std::size_t i = 1; sorted && i < pairs.size(); ++i) sorted = objects(i - 1) <= objects(i);
    std::span<std::uint32_t> order;
    if (!sorted) {
        // A stable counting sort by object pair (the pipeline sorts by first object and
        // triangle, so the second objects interleave; a frame has few object pairs).
        order = sized(order_kept);
        std::vector<std::pair<std::uint64_t, std::uint32_t>> counts;  // (object pair, pairs), by object pair
        for (std::uint32_t i = 0; i < pairs.size(); ++i) {
            const std::uint64_t key = objects(i);
            auto it = std::lower_bound(counts.begin(), counts.end(), std::pair(key, 0u));
            if (it == counts.end() || it->first != key) it = counts.insert(it, {key, 0u});
            ++it->second;
        }
        std::uint32_t start = 0;
        for (auto& [key, count] : counts) start += std::exchange(count, start);  // counts become starts
        for (std::uint32_t i = 0; i < pairs.size(); ++i) {
            order[std::lower_bound(counts.begin(), counts.end(), std::pair(objects(i), 0u))->second++] = i;
        }
    }
    const auto at = [&](std::size_t k) { return sorted ? static_cast<std::uint32_t>(k) : order[k]; };
    const std::span<std::uint32_t> set_of_pair = sized(set_kept);  // a vertex of its set (global numbering below)
    thread_local regions::StampedMarks joined_a, joined_b;  // triangles whose corners are joined
    std::uint32_t base = 0;                                 // object pairs' vertex ranges, one after another
    std::vector<std::uint32_t> parent;
    const auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    const auto unite = [&](std::uint32_t x, std::uint32_t y) {
        x = find(x);
        y = find(y);
        if (x != y) parent[std::max(x, y)] = std::min(x, y);  // the lower index is the root
    };
    struct Range {
        std::size_t begin, end;
        std::uint32_t base, vertices;
    };
    std::vector<Range> ranges;
    for (std::size_t begin = 0; begin < pairs.size();) {
        std::size_t end = begin;
        while (end < pairs.size() && objects(at(end)) == objects(at(begin))) ++end;
        const TrianglePair& first = pairs[at(begin)];
        const bool self = first.obj_a == first.obj_b;
        const std::uint32_t va = frame.objects[first.obj_a].topology->vertex_count;
        const std::uint32_t vb = self ? 0 : frame.objects[first.obj_b].topology->vertex_count;
        ranges.push_back({begin, end, base, va + vb});
        base += va + vb;
        begin = end;
    }
    parent.resize(base);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const Range& range : ranges) {
        const TrianglePair& first = pairs[at(range.begin)];
        const ObjectFrame& a = frame.objects[first.obj_a];
        const ObjectFrame& b = frame.objects[first.obj_b];
        const bool self = first.obj_a == first.obj_b;
        const std::uint32_t offset_b = range.base + (self ? 0 : a.topology->vertex_count);
        joined_a.next(a.triangle_count());
        if (!self) joined_b.next(b.triangle_count());
        regions::StampedMarks& marks_b = self ? joined_a : joined_b;
        const auto join_triangle = [&](const TriIndices& t, std::uint32_t offset, regions::StampedMarks& marks, std::uint32_t tri) {
            if (!marks.mark(tri)) return;
            unite(offset + t[0], offset + t[1]);
            unite(offset + t[0], offset + t[2]);
        };
        for (std::size_t k = range.begin; k < range.end; ++k) {
            const TrianglePair& pair = pairs[at(k)];
            const TriIndices& ta = a.topology->triangles[pair.tri_a];
            const TriIndices& tb = b.topology->triangles[pair.tri_b];
            join_triangle(ta, range.base, joined_a, pair.tri_a);
            join_triangle(tb, offset_b, marks_b, pair.tri_b);
            unite(range.base + ta[0], offset_b + tb[0]);
            set_of_pair[at(k)] = range.base + ta[0];
        }
    }
    // Regions in the order of their first pair; a counting pass sizes each before filling it.
    std::vector<std::uint32_t> region_of_root(base, UINT32_MAX);
    const std::span<std::uint32_t> region_of_pair = sized(region_kept);
    std::vector<std::uint32_t> sizes;
    for (std::uint32_t i = 0; i < pairs.size(); ++i) {
        std::uint32_t& region = region_of_root[find(set_of_pair[i])];
        if (region == UINT32_MAX) {
            region = static_cast<std::uint32_t>(sizes.size());
            sizes.push_back(0);
        }
        region_of_pair[i] = region;
        ++sizes[region];
    }
    std::vector<std::vector<std::uint32_t>> groups(sizes.size());
    for (std::size_t r = 0; r < groups.size(); ++r) groups[r].reserve(sizes[r]);
    for (std::uint32_t i = 0; i < pairs.size(); ++i) groups[region_of_pair[i]].push_back(i);
    return groups;
}

Region describe(const Frame& frame, std::span<const TrianglePair> pairs, std::span<const regions::Piece> pieces,
                std::vector<std::uint32_t> indices, const RegionOptions& options) {
    Region region;
    region.obj_a = pairs[indices.front()].obj_a;
    region.obj_b = pairs[indices.front()].obj_b;
    region.pairs = static_cast<std::uint32_t>(indices.size());
    std::vector<std::uint32_t>& side_a = region.triangles_a;
    std::vector<std::uint32_t>& side_b = region.triangles_b;
    const bool self = region.obj_a == region.obj_b;
    // A segment two pairs report with the same ends (an edge lying in the other surface, seen
    // from both of its triangles) counts once.
    std::vector<std::pair<std::pair<regions::EndKey, regions::EndKey>, std::uint32_t>> segments;
    // Each side's triangles once (a triangle is in many pairs of dense contact), sorted after.
    thread_local regions::StampedMarks marks_a, marks_b;
    marks_a.next(frame.objects[region.obj_a].triangle_count());
    marks_b.next(frame.objects[region.obj_b].triangle_count());
    regions::StampedMarks& other = self ? marks_a : marks_b;
    for (const std::uint32_t i : indices) {
        if (marks_a.mark(pairs[i].tri_a)) side_a.push_back(pairs[i].tri_a);
        if (other.mark(pairs[i].tri_b)) (self ? side_a : side_b).push_back(pairs[i].tri_b);
        const regions::Piece& piece = pieces[i];
        region.box.extend(piece.ends[0]);
        region.box.extend(piece.ends[1]);
        region.coplanar_area += piece.area;
        if (piece.kind == PairIntersection::Kind::Segment) {
            segments.push_back({std::minmax(piece.keys[0], piece.keys[1]), i});
        }
    }
    std::sort(segments.begin(), segments.end());
    std::vector<std::uint32_t> unique_segments;
    for (std::size_t k = 0; k < segments.size(); ++k) {
        if (k > 0 && segments[k].first == segments[k - 1].first && segments[k].first.first.valid) continue;
        const regions::Piece& piece = pieces[segments[k].second];
        region.curve_length += (piece.ends[1] - piece.ends[0]).norm();
        unique_segments.push_back(segments[k].second);
    }
    if (!std::is_sorted(side_a.begin(), side_a.end())) std::sort(side_a.begin(), side_a.end());
    if (!std::is_sorted(side_b.begin(), side_b.end())) std::sort(side_b.begin(), side_b.end());
    if (options.curves) {
        region.curves = regions::chain_curves(pieces, unique_segments);
        for (const IntersectionCurve& curve : region.curves) region.loops += curve.closed ? 1 : 0;
    }
    region.pair_indices = std::move(indices);
    return region;
}

}  // namespace

std::vector<Region> find_regions(const Frame& frame, std::span<const TrianglePair> pairs, const RegionOptions& options) {
    if (pairs.empty()) return {};
    // Kept from call to call on this thread: a dense frame's pieces are hundreds of megabytes,
    // and memory touched for the first time (the kernel zeroing its pages) cost as much as
    // filling it.
    thread_local std::vector<regions::Piece> kept;
    if (kept.size() < pairs.size()) kept.resize(pairs.size());
    const std::span<regions::Piece> pieces(kept.data(), pairs.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 1024), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) pieces[i] = regions::intersect(frame, pairs[i]);
    });
    std::vector<std::vector<std::uint32_t>> groups = group_pairs(frame, pairs);
    std::vector<Region> result(groups.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups.size(), 1), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r) {
            result[r] = describe(frame, pairs, pieces, std::move(groups[r]), options);
        }
    });
    if (options.penetration) regions::measure_penetration(frame, pairs, pieces, result);

    return result;
}

}  // namespace collidescope
