// A frame's regions: every pair's intersection (in parallel), the pairs joined into regions by
// the vertices their triangles share (a union-find), then each
// region's counts, box and curves (in parallel over regions).

#include "curves.hpp"
#include "pair_intersection.hpp"
#include "penetration.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace collidescope {
namespace {

// Union-find over pair indices, by size, with path halving.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : m_parent(n), m_size(n, 1) { std::iota(m_parent.begin(), m_parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (m_parent[x] != x) x = m_parent[x] = m_parent[m_parent[x]];
        return x;
    }
    void unite(std::uint32_t x, std::uint32_t y) {
        x = find(x);
        y = find(y);
        if (x == y) return;
        if (m_size[x] < m_size[y]) std::swap(x, y);
        m_parent[y] = x;
        m_size[x] += m_size[y];
    }

private:
    std::vector<std::uint32_t> m_parent;
    std::vector<std::uint32_t> m_size;
};

// The pairs of each region, regions ordered by their first pair. Within the pairs of one
// object pair, a pair joins the first pair seen at
// each of its six vertices (dense arrays over the objects' vertices, reset where touched).
std::vector<std::vector<std::uint32_t>> group_pairs(const Frame& frame, std::span<const TrianglePair> pairs) {
    DisjointSets sets(pairs.size());
    std::size_t most_vertices = 0;
    for (const ObjectFrame& object : frame.objects) most_vertices = std::max<std::size_t>(most_vertices, object.topology->vertex_count);
    std::vector<std::uint32_t> first_a(most_vertices, UINT32_MAX), first_b(most_vertices, UINT32_MAX);
    const auto join = [&](std::vector<std::uint32_t>& first, std::uint32_t vertex, std::uint32_t pair) {
        if (first[vertex] == UINT32_MAX) {
            first[vertex] = pair;
        } else {
            sets.unite(pair, first[vertex]);
        }
    };
    // The pairs in object-pair order (the pipeline's sorted pairs already are).
    const auto objects = [&](std::uint32_t i) { return std::uint64_t(pairs[i].obj_a) << 32 | pairs[i].obj_b; };
    std::vector<std::uint32_t> order(pairs.size());
    std::iota(order.begin(), order.end(), 0u);
    if (!std::is_sorted(order.begin(), order.end(), [&](auto x, auto y) { return objects(x) < objects(y); })) {
        std::stable_sort(order.begin(), order.end(), [&](auto x, auto y) { return objects(x) < objects(y); });
    }
    for (std::size_t begin = 0; begin < order.size();) {
        std::size_t end = begin;
        while (end < order.size() && objects(order[end]) == objects(order[begin])) ++end;
        const TrianglePair& first = pairs[order[begin]];
        const ObjectFrame& a = frame.objects[first.obj_a];
        const ObjectFrame& b = frame.objects[first.obj_b];
        // Self pairs: both triangles' vertices are one object's, in one array.
        std::vector<std::uint32_t>& side_b = first.obj_a == first.obj_b ? first_a : first_b;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = order[k];
            for (const std::uint32_t v : a.topology->triangles[pairs[i].tri_a]) join(first_a, v, i);
            for (const std::uint32_t v : b.topology->triangles[pairs[i].tri_b]) join(side_b, v, i);
        }
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = order[k];
            for (const std::uint32_t v : a.topology->triangles[pairs[i].tri_a]) first_a[v] = UINT32_MAX;
            for (const std::uint32_t v : b.topology->triangles[pairs[i].tri_b]) side_b[v] = UINT32_MAX;
        }
        begin = end;
    }
    std::vector<std::uint32_t> region_of_root(pairs.size(), UINT32_MAX);
    std::vector<std::vector<std::uint32_t>> groups;
    for (std::uint32_t i = 0; i < pairs.size(); ++i) {
        std::uint32_t& region = region_of_root[sets.find(i)];
        if (region == UINT32_MAX) {
            region = static_cast<std::uint32_t>(groups.size());
            groups.emplace_back();
        }
        groups[region].push_back(i);
    }
    return groups;
}

// Sorted, each once (pairs come sorted by their first triangle, so side A often already is).
void sort_unique(std::vector<std::uint32_t>& values) {
    if (!std::is_sorted(values.begin(), values.end())) std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
}

Region describe(std::span<const TrianglePair> pairs, std::span<const regions::Piece> pieces,
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
    for (const std::uint32_t i : indices) {
        side_a.push_back(pairs[i].tri_a);
        (self ? side_a : side_b).push_back(pairs[i].tri_b);
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
    sort_unique(side_a);
    sort_unique(side_b);
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
    std::vector<regions::Piece> pieces(pairs.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 1024), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) pieces[i] = regions::intersect(frame, pairs[i]);
    });
    std::vector<std::vector<std::uint32_t>> groups = group_pairs(frame, pairs);
    std::vector<Region> result(groups.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups.size(), 1), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r) {
            result[r] = describe(pairs, pieces, std::move(groups[r]), options);
        }
    });
    if (options.penetration) regions::measure_penetration(frame, pairs, pieces, result);
    return result;
}

}  // namespace collidescope
