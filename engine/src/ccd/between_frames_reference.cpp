// The reference for between-frames detection: every triangle pair of every object pair (and
// of each object with itself, i < j, with self-collision), no trees; a pair whose swept boxes
// (the box of its corners at both ends, which holds the triangle throughout the linear motion)
// are apart cannot touch; otherwise a pair
// touching at t = 0 by the exact per-frame test (the self rule for one object), else each of
// its fifteen queries by interval bisection (interval_reference.hpp), minus those whose two
// features share a vertex index within one object; the earliest contact over them.

#include "collidescope/between_frames.hpp"

#include "ccd/interval_checks.hpp"
#include "ccd/interval_reference.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>

namespace collidescope {
namespace {

struct Triangle {
    std::array<ccd::Path, 3> corners;
    TriIndices ids;
};

Triangle triangle(const Frame& from, const Frame& to, std::uint32_t object, std::uint32_t tri) {
    Triangle t;
    t.ids = from.objects[object].topology->triangles[tri];
    for (int i = 0; i < 3; ++i) t.corners[i] = {from.objects[object].vertices[t.ids[i]], to.objects[object].vertices[t.ids[i]]};
    return t;
}

bool touching_at(const Triangle& a, const Triangle& b, bool self, int end) {
    const std::array<Vec3, 3> pa{a.corners[0][end], a.corners[1][end], a.corners[2][end]};
    const std::array<Vec3, 3> pb{b.corners[0][end], b.corners[1][end], b.corners[2][end]};
    return self ? self_triangles_collide(a.ids, pa, b.ids, pb) : triangles_intersect(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
}

// The box of a triangle's corners at both ends, as (lo, hi).
std::pair<Vec3, Vec3> swept_box(const Triangle& t) {
    Vec3 lo = t.corners[0][0], hi = lo;
    for (const ccd::Path& path : t.corners) {
        for (const Vec3& p : path) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    }
    return {lo, hi};
}

bool in(const TriIndices& t, std::uint32_t v) { return std::find(t.begin(), t.end(), v) != t.end(); }

void test(const TrianglePair& pair, const Triangle& a, const Triangle& b, bool self, const BetweenFramesOptions& options,
          double tolerance, IntervalResult& result) {
    if (self && std::is_permutation(a.ids.begin(), a.ids.end(), b.ids.begin())) return;
    const auto [a_lo, a_hi] = swept_box(a);
    const auto [b_lo, b_hi] = swept_box(b);
    if ((a_lo.array() > b_hi.array()).any() || (b_lo.array() > a_hi.array()).any()) return;
    ++result.stats.candidate_pairs;
    const bool start = touching_at(a, b, self, 0);
    if (start) {
        result.contacts.push_back({pair, 0.0, false, true});
        ++result.stats.start_contacts;
        return;
    }
    ccd::QueryConfig config{tolerance, 1, options.max_boxes};
    bool contact = false, resolved = true;
    double toi = 1;
    const auto take = [&](const ccd::QueryResult& r) {
        ++result.stats.primitive_queries;
        result.stats.inclusion_boxes += r.boxes;
        if (!r.hit) return;
        toi = contact ? std::min(toi, r.toi) : r.toi;
        contact = true;
        resolved = resolved && r.resolved;
    };
    for (int i = 0; i < 3; ++i) {
        if (!(self && in(b.ids, a.ids[i]))) take(ccd::reference::vertex_face(a.corners[i], b.corners[0], b.corners[1], b.corners[2], config));
        if (!(self && in(a.ids, b.ids[i]))) take(ccd::reference::vertex_face(b.corners[i], a.corners[0], a.corners[1], a.corners[2], config));
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const std::uint32_t a0 = a.ids[i], a1 = a.ids[(i + 1) % 3], b0 = b.ids[j], b1 = b.ids[(j + 1) % 3];
            if (self && (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1)) continue;
            take(ccd::reference::edge_edge(a.corners[i], a.corners[(i + 1) % 3], b.corners[j], b.corners[(j + 1) % 3], config));
        }
    }
    if (contact) result.contacts.push_back({pair, toi, !touching_at(a, b, self, 1), resolved});
}

}  // namespace

IntervalResult between_frames_reference(const Frame& from, const Frame& to, const BetweenFramesOptions& options) {
    const double tolerance = ccd::check_interval(from, to, options.tolerance);
    IntervalResult result;
    result.stats.tolerance = tolerance;
    const auto n = static_cast<std::uint32_t>(from.objects.size());
    for (std::uint32_t x = 0; x < n; ++x) {
        const auto tx = static_cast<std::uint32_t>(from.objects[x].triangle_count());
        for (std::uint32_t y = x; y < n; ++y) {
            const bool self = x == y;
            if (self && !options.self_collision) continue;
            const auto ty = static_cast<std::uint32_t>(from.objects[y].triangle_count());
            for (std::uint32_t i = 0; i < tx; ++i) {
                const Triangle a = triangle(from, to, x, i);
                for (std::uint32_t j = self ? i + 1 : 0; j < ty; ++j) {
                    test({x, i, y, j}, a, triangle(from, to, y, j), self, options, tolerance, result);
                }
            }
        }
    }
    for (const IntervalContact& c : result.contacts) {
        result.stats.pass_throughs += c.pass_through;
        result.stats.unresolved += !c.resolved;
    }
    result.stats.contacts = result.contacts.size();
    return result;
}

}  // namespace collidescope
