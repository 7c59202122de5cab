// A frame's regions: the pairs joined into regions by the vertices their triangles share (a
// union-find), then each region's intersections, counts, box and curves (in parallel over
// regions, and over the pairs of a large region).

#include "curves.hpp"
#include "first_seen.hpp"
#include "mesh_shape.hpp"
#include "pair_intersection.hpp"
#include "penetration.hpp"
#include "stamped_marks.hpp"

#include "collidescope/large_blocks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <memory>
#include <new>
#include <numeric>
#include <utility>

namespace collidescope {
namespace {

// The working arrays as long as a frame's pairs or segments are large blocks once they are
// large (collidescope/large_blocks.hpp): a fresh 4 KiB page costs 13.7 us on the project's VM,
// and a dense frame's first regions touched megabytes of them (cloth-drape's first colliding
// frame: most of its regions' time).
using detail::LargeVector;

// Numbers for the vertices of one mesh that one object pair's colliding triangles use, given in
// the order they are met, each also a new set of the union-find (`parent`). Reset in O(1)
// for the next object pair (a stamp per vertex, as StampedMarks).
struct VertexNumbers {
    regions::StampedMarks seen;
    LargeVector<std::uint32_t> number;

    void next(std::size_t vertices) {
        seen.next(vertices);
        if (number.size() < vertices) number.resize(vertices);
    }
    std::uint32_t of(std::uint32_t vertex, LargeVector<std::uint32_t>& parent) {
        if (seen.mark(vertex)) {
            number[vertex] = static_cast<std::uint32_t>(parent.size());
            parent.push_back(number[vertex]);
        }
        return number[vertex];
    }
};

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
    thread_local LargeVector<std::uint32_t> order_kept, set_kept, region_kept;
    const auto sized = [&](LargeVector<std::uint32_t>& kept) {
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
        // A slot per object pair, looked up in a table of every (a, b) where the objects are few.
        std::vector<std::pair<std::uint64_t, std::uint32_t>> counts;  // (object pair, pairs), by object pair
        const std::size_t n = frame.objects.size();
        std::vector<std::uint32_t> table(n * n <= (1u << 16) ? n * n : 0, UINT32_MAX);
        for (std::uint32_t i = 0; i < pairs.size(); ++i) {
            const std::uint64_t key = objects(i);
            auto it = std::lower_bound(counts.begin(), counts.end(), std::pair(key, 0u));
            if (it == counts.end() || it->first != key) it = counts.insert(it, {key, 0u});
            if (i + 1 < pairs.size() && objects(i + 1) == key) {
                // A run of one object pair (runs are common): counted without searching.
                std::uint32_t j = i + 1;
                while (j < pairs.size() && objects(j) == key) ++j;
                it->second += j - i;
                i = j - 1;
                continue;
            }
            ++it->second;
        }
        std::uint32_t start = 0;
        for (auto& [key, count] : counts) start += std::exchange(count, start);  // counts become starts
        const auto slot = [&](std::size_t i) -> std::uint32_t& {
            return std::lower_bound(counts.begin(), counts.end(), std::pair(objects(i), 0u))->second;
        };
        if (!table.empty()) {
            for (std::uint32_t k = 0; k < counts.size(); ++k) {
                table[(counts[k].first >> 32) * n + (counts[k].first & 0xffffffffu)] = k;
            }
        }
        for (std::uint32_t i = 0; i < pairs.size(); ++i) {
            std::uint32_t& next = table.empty() ? slot(i) : counts[table[pairs[i].obj_a * n + pairs[i].obj_b]].second;
            order[next++] = i;
        }
    }
    const auto at = [&](std::size_t k) { return sorted ? static_cast<std::uint32_t>(k) : order[k]; };
    // Each pair's set: first the root of its set among its object pair's numbers, then (offset
    // by the numbers of the object pairs before) among the frame's.
    const std::span<std::uint32_t> root_of_pair = sized(set_kept);
    struct Range {
        std::size_t begin, end;
        std::uint32_t numbers = 0;  ///< how many its unions used; then where they start among the frame's
    };
    std::vector<Range> ranges;
    for (std::size_t begin = 0; begin < pairs.size();) {
        std::size_t end = begin;
        while (end < pairs.size() && objects(at(end)) == objects(at(begin))) ++end;
        ranges.push_back({begin, end});
        begin = end;
    }
    // Object pairs are independent: their unions run in parallel, each over numbers of its own
    // given to the vertices its colliding triangles use, in the order met (as many as those
    // vertices, where a number per vertex of both meshes cost a frame of a fragmented mesh
    // clearing arrays as long as its vertices: half the regions' time on data set E).
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ranges.size(), 1), [&](const auto& chunk) {
        // Per thread (a range is worked on by one thread): triangles whose corners are joined,
        // each side's vertex numbers, and the union-find over them.
        static thread_local regions::StampedMarks joined_a, joined_b;
        static thread_local VertexNumbers numbers_a, numbers_b;
        static thread_local LargeVector<std::uint32_t> parent;
        const auto find = [&](std::uint32_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        const auto unite = [&](std::uint32_t x, std::uint32_t y) {
            x = find(x);
            y = find(y);
            if (x != y) parent[std::max(x, y)] = std::min(x, y);  // the lower number is the root
        };
        for (std::size_t r = chunk.begin(); r != chunk.end(); ++r) {
            Range& range = ranges[r];
            const TrianglePair& first = pairs[at(range.begin)];
            const ObjectFrame& a = frame.objects[first.obj_a];
            const ObjectFrame& b = frame.objects[first.obj_b];
            const bool self = first.obj_a == first.obj_b;
            parent.clear();
            joined_a.next(a.triangle_count());
            numbers_a.next(a.topology->vertex_count);
            if (!self) {
                joined_b.next(b.triangle_count());
                numbers_b.next(b.topology->vertex_count);
            }
            regions::StampedMarks& marks_b = self ? joined_a : joined_b;
            VertexNumbers& vertices_b = self ? numbers_a : numbers_b;
            const auto join_triangle = [&](const TriIndices& t, VertexNumbers& numbers, regions::StampedMarks& marks,
                                           std::uint32_t tri) {
                if (!marks.mark(tri)) return;
                const std::uint32_t v0 = numbers.of(t[0], parent);
                unite(v0, numbers.of(t[1], parent));
                unite(v0, numbers.of(t[2], parent));
            };
            for (std::size_t k = range.begin; k < range.end; ++k) {
                const TrianglePair& pair = pairs[at(k)];
                const TriIndices& ta = a.topology->triangles[pair.tri_a];
                const TriIndices& tb = b.topology->triangles[pair.tri_b];
                join_triangle(ta, numbers_a, joined_a, pair.tri_a);
                join_triangle(tb, vertices_b, marks_b, pair.tri_b);
                const std::uint32_t va = numbers_a.of(ta[0], parent);
                unite(va, vertices_b.of(tb[0], parent));
                root_of_pair[at(k)] = va;
            }
            for (std::size_t k = range.begin; k < range.end; ++k) root_of_pair[at(k)] = find(root_of_pair[at(k)]);
            range.numbers = static_cast<std::uint32_t>(parent.size());
        }
    });
    std::uint32_t total = 0;
    for (Range& range : ranges) total += std::exchange(range.numbers, total);  // counts become offsets
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ranges.size(), 1), [&](const auto& chunk) {
        for (std::size_t r = chunk.begin(); r != chunk.end(); ++r) {
            if (ranges[r].numbers == 0) continue;
            for (std::size_t k = ranges[r].begin; k < ranges[r].end; ++k) root_of_pair[at(k)] += ranges[r].numbers;
        }
    });
    // Regions in the order of their first pair; a counting pass sizes each before filling it.
    LargeVector<std::uint32_t> region_of_root(total, UINT32_MAX);
    const std::span<std::uint32_t> region_of_pair = sized(region_kept);
    std::vector<std::uint32_t> sizes;
    for (std::uint32_t i = 0; i < pairs.size(); ++i) {
        std::uint32_t& region = region_of_root[root_of_pair[i]];
        if (region == UINT32_MAX) {
            region = static_cast<std::uint32_t>(sizes.size());
            sizes.push_back(0);
        }
        region_of_pair[i] = region;
        ++sizes[region];
    }
    std::vector<std::vector<std::uint32_t>> groups(sizes.size());
    if (groups.size() == 1) {  // one region (dense contact often is): every pair
        groups[0].resize(pairs.size());
        std::iota(groups[0].begin(), groups[0].end(), 0u);
        return groups;
    }
    for (std::size_t r = 0; r < groups.size(); ++r) groups[r].reserve(sizes[r]);
    for (std::uint32_t i = 0; i < pairs.size(); ++i) groups[region_of_pair[i]].push_back(i);
    return groups;
}

// A frame's pieces, one slot per pair, kept from call to call on its thread and never
// initialised: only a segment's piece, or every piece of a measured region, is written (a
// coplanar frame writes almost none) and only those are read. Memory touched for the first time
// (the kernel zeroing its pages) cost as much as filling it: value-initialising the slots of a
// growing vector made the first two frames of cloth-slide 6x dearer than the rest. Growing
// copies nothing (a frame's pieces are that frame's only). A large block once large.
class PieceBuffer {
public:
    PieceBuffer() = default;
    PieceBuffer(const PieceBuffer&) = delete;
    PieceBuffer& operator=(const PieceBuffer&) = delete;
    ~PieceBuffer() { release(); }

    std::span<regions::Piece> get(std::size_t pairs) {
        if (pairs > m_capacity) {
            release();
            m_data = Allocator().allocate(2 * pairs);
            m_capacity = 2 * pairs;
        }
        return {m_data, pairs};
    }

private:
    using Allocator = detail::LargeBlockAllocator<regions::Piece>;
    void release() {
        if (m_data) Allocator().deallocate(m_data, m_capacity);
        m_data = nullptr;
        m_capacity = 0;
    }
    regions::Piece* m_data = nullptr;
    std::size_t m_capacity = 0;
};

// What a region gathers from its pairs' pieces: their box, the coplanar area, and its
// segments by their ends' keys (a segment two pairs report with the same ends, an edge lying in
// the other surface seen from both of its triangles, counts once).
struct Gathered {
    Eigen::AlignedBox3d box;
    double coplanar_area = 0;
    struct Segment {
        std::uint64_t hash;  ///< of both keys: equal ends, equal hashes
        std::uint32_t pair;  ///< its piece holds the keys
    };
    LargeVector<Segment> segments;

    void join(Gathered& other) {
        box.extend(other.box);
        coplanar_area += other.coplanar_area;
        segments.insert(segments.end(), other.segments.begin(), other.segments.end());
    }
};

// Pairs a thread intersects at a time: a region of a few thousand pairs (a frame of data set B,
// cloth-drape) is split over the threads, where 4,096 kept them on one.
constexpr std::size_t k_intersect_grain = 512;

// A region's pairs' intersections, gathered, and kept in `pieces`: the segments (the curves
// need them), and every piece when `keep_all` (the penetration measure reads them all). In
// parallel over the pairs of a large region (dense contact is often one region), split the same
// way on any number of threads, so the sums are the same.
Gathered intersect_region(const Frame& frame, std::span<const TrianglePair> pairs, std::span<regions::Piece> pieces,
                          std::span<const std::uint32_t> indices, bool keep_all) {
    const auto intersect_range = [&](const tbb::blocked_range<std::size_t>& range, Gathered gathered) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const std::uint32_t i = indices[k];
            const regions::Piece piece = regions::intersect(frame, pairs[i]);
            gathered.box.extend(piece.ends[0]);
            gathered.box.extend(piece.ends[1]);
            gathered.coplanar_area += piece.area;
            if (piece.kind == PairIntersection::Kind::Segment) {
                std::construct_at(&pieces[i], piece);
                const std::uint64_t h0 = regions::key_hash(piece.keys[0]), h1 = regions::key_hash(piece.keys[1]);
                gathered.segments.push_back({std::min(h0, h1) * 31 + std::max(h0, h1), i});
            } else if (keep_all) {
                std::construct_at(&pieces[i], piece);  // only then: a dense frame's pieces are gigabytes a second
            }
        }
        return gathered;
    };
    // A region within one grain is one range whatever the threads: called directly, the same
    // result without a reduction's set-up (data set E's 500 regions of a pair or two a frame).
    if (indices.size() <= k_intersect_grain) return intersect_range({0, indices.size()}, Gathered{});
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, indices.size(), k_intersect_grain), Gathered{}, intersect_range,
        [](Gathered a, Gathered b) {
            a.join(b);
            return a;
        });
}

// Pairs from which a region's two sides are collected on two threads.
constexpr std::size_t k_parallel_sides = 4096;

// The triangles of a region's pairs on side a (`a`), side b (`b`) or both, each once, sorted:
// marked, then listed by a scan of the marks where they are many (dense contact marks much of
// a mesh, and sorting them was a twentieth of the regions' time on cloth-slide), else sorted.
std::vector<std::uint32_t> side_triangles(std::span<const TrianglePair> pairs, std::span<const std::uint32_t> indices,
                                          std::size_t triangle_count, bool a, bool b) {
    thread_local regions::StampedMarks marks;
    marks.next(triangle_count);
    std::vector<std::uint32_t> side;
    for (const std::uint32_t i : indices) {
        if (a && marks.mark(pairs[i].tri_a)) side.push_back(pairs[i].tri_a);
        if (b && marks.mark(pairs[i].tri_b)) side.push_back(pairs[i].tri_b);
    }
    if (std::is_sorted(side.begin(), side.end())) return side;
    if (side.size() < triangle_count / 16) {
        std::sort(side.begin(), side.end());
        return side;
    }
    std::size_t k = 0;
    for (std::size_t t = 0; t < triangle_count; ++t) {
        if (marks.marked(t)) side[k++] = static_cast<std::uint32_t>(t);
    }
    return side;
}

Region describe(const Frame& frame, std::span<const TrianglePair> pairs, std::span<regions::Piece> pieces,
                std::vector<std::uint32_t> indices, const RegionOptions& options, std::span<const char> closed) {
    Region region;
    region.obj_a = pairs[indices.front()].obj_a;
    region.obj_b = pairs[indices.front()].obj_b;
    region.pairs = static_cast<std::uint32_t>(indices.size());
    const bool measured =
        options.penetration && region.obj_a != region.obj_b && (closed[region.obj_a] || closed[region.obj_b]);
    Gathered gathered = intersect_region(frame, pairs, pieces, indices, measured);
    region.box = gathered.box;
    region.coplanar_area = gathered.coplanar_area;
    auto& segments = gathered.segments;
    // Each side's triangles (self-contact: one side, both triangles); a large region's two
    // sides at once (a small one's are cheaper than handing one to another thread).
    const std::size_t count_a = frame.objects[region.obj_a].triangle_count();
    const std::size_t count_b = frame.objects[region.obj_b].triangle_count();
    if (region.obj_a == region.obj_b) {
        region.triangles_a = side_triangles(pairs, indices, count_a, true, true);
    } else if (indices.size() < k_parallel_sides) {
        region.triangles_a = side_triangles(pairs, indices, count_a, true, false);
        region.triangles_b = side_triangles(pairs, indices, count_b, false, true);
    } else {
        tbb::parallel_invoke([&] { region.triangles_a = side_triangles(pairs, indices, count_a, true, false); },
                             [&] { region.triangles_b = side_triangles(pairs, indices, count_b, false, true); });
    }
    // A segment reported again with the same ends (keys with features) counts once: the first.
    const auto keys = [&](const Gathered::Segment& x) {
        return std::minmax(pieces[x.pair].keys[0], pieces[x.pair].keys[1]);
    };
    regions::FirstSeen seen(segments.size());
    std::vector<std::uint32_t> unique_segments;
    for (std::uint32_t k = 0; k < segments.size(); ++k) {
        const auto ends = keys(segments[k]);
        if (ends.first.valid &&
            seen.find_or_add(segments[k].hash, k, [&](std::uint32_t j) { return keys(segments[j]) == ends; }) != k) {
            continue;
        }
        const regions::Piece& piece = pieces[segments[k].pair];
        region.curve_length += (piece.ends[1] - piece.ends[0]).norm();
        unique_segments.push_back(segments[k].pair);
    }
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
    thread_local PieceBuffer kept;
    const std::span<regions::Piece> pieces = kept.get(pairs.size());
    std::vector<std::vector<std::uint32_t>> groups = group_pairs(frame, pairs);
    std::vector<Region> result(groups.size());
    // Which objects of the regions between two objects are closed, looked up once per object
    // (not per region: data set E has 500 regions a frame).
    std::vector<char> closed(frame.objects.size(), 0);
    if (options.penetration) {
        std::vector<char> looked(frame.objects.size(), 0);
        for (const std::vector<std::uint32_t>& group : groups) {
            const TrianglePair& first = pairs[group.front()];
            if (first.obj_a == first.obj_b) continue;  // self-contact is not measured
            for (const std::uint32_t object : {first.obj_a, first.obj_b}) {
                if (std::exchange(looked[object], 1) == 0) closed[object] = regions::mesh_shape(*frame.objects[object].topology)->closed;
            }
        }
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups.size(), 1), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r) {
            result[r] = describe(frame, pairs, pieces, std::move(groups[r]), options, closed);
        }
    });
    if (options.penetration) regions::measure_penetration(frame, pairs, pieces, result);

    return result;
}

}  // namespace collidescope
