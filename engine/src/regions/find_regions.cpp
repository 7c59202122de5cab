// A frame's regions: every pair's intersection (in parallel), the pairs joined into regions by
// the vertices their triangles share (a union-find over runs of equal vertex keys), then each
// region's counts, box and curves (in parallel over regions).

#include "curves.hpp"
#include "pair_intersection.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

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

// A vertex of one side of one object pair: pairs holding the same key touch there.
struct VertexKey {
    std::uint64_t objects;  ///< obj_a << 32 | obj_b
    std::uint64_t vertex;   ///< side << 32 | vertex id (self pairs: side 0 for both triangles)
    std::uint32_t pair;
    bool operator<(const VertexKey& o) const {
        return objects != o.objects ? objects < o.objects : vertex != o.vertex ? vertex < o.vertex : pair < o.pair;
    }
};

// The pairs of each region, regions ordered by their first pair.
std::vector<std::vector<std::uint32_t>> group_pairs(const Frame& frame, std::span<const TrianglePair> pairs) {
    std::vector<VertexKey> keys(pairs.size() * 6);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 4096), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const TrianglePair& p = pairs[i];
            const std::uint64_t objects = std::uint64_t(p.obj_a) << 32 | p.obj_b;
            const std::uint64_t side_b = p.obj_a == p.obj_b ? 0 : std::uint64_t(1) << 32;
            const TriIndices& a = frame.objects[p.obj_a].topology->triangles[p.tri_a];
            const TriIndices& b = frame.objects[p.obj_b].topology->triangles[p.tri_b];
            for (int k = 0; k < 3; ++k) {
                keys[6 * i + k] = {objects, a[k], static_cast<std::uint32_t>(i)};
                keys[6 * i + 3 + k] = {objects, side_b | b[k], static_cast<std::uint32_t>(i)};
            }
        }
    });
    tbb::parallel_sort(keys.begin(), keys.end());
    DisjointSets sets(pairs.size());
    for (std::size_t i = 1; i < keys.size(); ++i) {
        if (keys[i].objects == keys[i - 1].objects && keys[i].vertex == keys[i - 1].vertex) {
            sets.unite(keys[i].pair, keys[i - 1].pair);
        }
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

std::uint32_t distinct(std::vector<std::uint64_t>& values) {
    std::sort(values.begin(), values.end());
    return static_cast<std::uint32_t>(std::unique(values.begin(), values.end()) - values.begin());
}

Region describe(std::span<const TrianglePair> pairs, std::span<const regions::Piece> pieces,
                std::vector<std::uint32_t> indices, const RegionOptions& options) {
    Region region;
    region.obj_a = pairs[indices.front()].obj_a;
    region.obj_b = pairs[indices.front()].obj_b;
    region.pairs = static_cast<std::uint32_t>(indices.size());
    std::vector<std::uint64_t> side_a, side_b;
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
    region.triangles_a = distinct(side_a);
    region.triangles_b = distinct(side_b);
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
    return result;
}

}  // namespace collidescope
