// The part of one object's surface (X) inside a closed object (Y), found from the curves
// alone, without a point-in-mesh query.
//
// Orient each intersection segment of a triangle T of X with one of Y's faces F along
// n_T x n_F (F's normal pointing out of Y): Y's inside then lies on the segment's left, seen
// from T's front. The part of T inside Y is bounded by those segments and by the pieces of
// T's edges inside Y, all run counterclockwise, so its area is the contour sum
// 1/2 n_T . sum (p x q) (Green's theorem), which needs no chaining. Which edge pieces are
// inside follows from the segments too: walking T's border counterclockwise, a segment that
// ends on the border is where the walk enters Y, one that starts there where it leaves. A
// triangle no segment reaches the border of (Y pokes through its middle) is inside along its
// whole border exactly when the segments' sum is negative (their loop encloses the outside).
// The walk also gives T's corners as inside or not. From the inside corners a flood over X's
// triangles that meet nothing of Y (entirely inside, then) adds their areas and corners, and
// the depth is the largest distance from those corners to Y's surface.

#include "penetration.hpp"

#include "mesh_shape.hpp"
#include "stamped_marks.hpp"
#include "surface_distance.hpp"

#include "collidescope/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace collidescope::regions {
namespace {

constexpr double k_undefined = std::numeric_limits<double>::quiet_NaN();

enum class Status : std::int8_t { Unknown, Outside, Inside };

// A segment in the direction with Y's inside on its left; `weight` +1, or less where several
// faces of Y report the same segment (a segment along an edge of Y counts once when Y
// crosses T there, and not at all where Y only touches T along it). Where an end lies on T's
// border, how the counterclockwise walk along the border changes there: +1 it enters Y, -1 it
// leaves, 0 it touches (decided by exact signs where they decide it: the orientation of a very
// short segment, from its rounded ends, does not).
struct Oriented {
    Vec3 from, to;
    EndKey from_key, to_key;
    double weight = 1;
    std::optional<double> from_position, to_position;  ///< on T's border
    double from_change = 0, to_change = 0;
};

// Where a point lies on T's border, counterclockwise from corner 0 (corner k at k, edge k from
// corner k to k + 1 in [k, k + 1)), or nothing when inside T.
std::optional<double> border_position(const EndKey& key, std::uint32_t object, const TriIndices& ids,
                                      const std::array<Vec3, 3>& corners, const Vec3& point) {
    if (!key.valid) return std::nullopt;
    const Feature& f = key.first.object == object ? key.first : key.second;
    if (f.object != object || f.kind == Feature::Face) return std::nullopt;
    for (int k = 0; k < 3; ++k) {
        if (f.kind == Feature::Vertex && ids[k] == f.a) return double(k);
        const std::uint32_t u = ids[k], v = ids[(k + 1) % 3];
        if (f.kind == Feature::Edge && std::min(u, v) == f.a && std::max(u, v) == f.b) {
            const Vec3 edge = corners[(k + 1) % 3] - corners[k];
            const double length = edge.squaredNorm();
            const double t = length > 0 ? std::clamp((point - corners[k]).dot(edge) / length, 0.0, 1.0) : 0.0;
            return k + t;
        }
    }
    return std::nullopt;
}

struct TriangleMeasure {
    double inside_area = 0;
    std::array<Status, 3> corners{Status::Unknown, Status::Unknown, Status::Unknown};
};

// Where a segment meets the border of the triangle.
struct Event {
    double position;
    double change;  ///< +: the walk enters Y here
    Vec3 point;
};

// measure_triangle's working arrays, kept from triangle to triangle (allocating them for
// each was a fifth of its time on small frames).
struct BorderWalk {
    std::vector<Event> events;
    std::vector<double> after;
};

// The part of triangle `tri` of X inside Y, from its segments.
TriangleMeasure measure_triangle(const ObjectFrame& x, std::uint32_t tri, std::span<const Oriented> segments,
                                 BorderWalk& walk) {
    TriangleMeasure result;
    const std::array<Vec3, 3> c = x.corners(tri);
    const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
    const double twice_area = normal.norm();
    if (!(twice_area > 0) || segments.empty()) return result;
    const Vec3 unit = normal / twice_area;
    const Vec3& origin = c[0];
    const auto contour = [&](const Vec3& p, const Vec3& q) { return 0.5 * unit.dot((p - origin).cross(q - origin)); };

    double area = 0;
    std::vector<Event>& events = walk.events;
    events.clear();
    for (const Oriented& s : segments) {
        area += s.weight * contour(s.from, s.to);
        if (s.from_position) events.push_back({*s.from_position, s.from_change, s.from});
        if (s.to_position) events.push_back({*s.to_position, s.to_change, s.to});
    }
    if (events.empty()) {
        const bool inside = area < 0;
        if (inside) area += 0.5 * twice_area;
        result.inside_area = std::clamp(area, 0.0, 0.5 * twice_area);
        result.corners.fill(inside ? Status::Inside : Status::Outside);
        return result;
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.position < b.position; });
    // Status after each event, up to the unknown status at corner 0: the lowest prefix sum is
    // outside.
    std::vector<double>& after = walk.after;
    after.resize(events.size());
    double sum = 0, lowest = 0;
    for (std::size_t k = 0; k < events.size(); ++k) {
        sum += events[k].change;
        after[k] = sum;
        lowest = std::min(lowest, sum);
    }
    const auto inside_after = [&](std::size_t k) { return after[k] - lowest > 0.5; };
    // The border from each event to the next (the last one round past corner 0 to the first).
    for (std::size_t k = 0; k < events.size(); ++k) {
        if (!inside_after(k)) continue;
        const std::size_t next = (k + 1) % events.size();
        const double from = events[k].position;
        const double to = next > k ? events[next].position : events[next].position + 3;
        Vec3 p = events[k].point;
        for (int corner = static_cast<int>(std::floor(from)) + 1; corner < to; ++corner) {
            const Vec3& q = c[corner % 3];
            area += contour(p, q);
            p = q;
        }
        area += contour(p, events[next].point);
    }
    result.inside_area = std::clamp(area, 0.0, 0.5 * twice_area);
    // Corner k is inside when the walk is inside there (on Y's surface: not inside).
    for (int corner = 0; corner < 3; ++corner) {
        bool on_surface = false;
        std::size_t last = events.size() - 1;  // the last event before the corner, cyclically
        for (std::size_t k = 0; k < events.size(); ++k) {
            if (events[k].position == corner || events[k].position == corner + 3) on_surface = true;
            if (events[k].position < corner) last = k;
        }
        result.corners[corner] = on_surface ? Status::Outside : inside_after(last) ? Status::Inside : Status::Outside;
    }
    return result;
}

// Six times the signed volume of a closed mesh (the sum of its triangles' tetrahedra with its
// first vertex), in scalars: through Vec3 temporaries the loop stalled on partial stores.
double signed_volume(const ObjectFrame& mesh) {
    if (mesh.vertices.size() == 0) return 0;
    const double ox = mesh.vertices[0].x(), oy = mesh.vertices[0].y(), oz = mesh.vertices[0].z();
    const std::span<const TriIndices> triangles = mesh.topology->triangles;
    const Vec3* v = mesh.vertices.span().data();
    double volume = 0;
    for (const TriIndices& t : triangles) {
        const double ax = v[t[0]].x() - ox, ay = v[t[0]].y() - oy, az = v[t[0]].z() - oz;
        const double bx = v[t[1]].x() - ox, by = v[t[1]].y() - oy, bz = v[t[1]].z() - oz;
        const double cx = v[t[2]].x() - ox, cy = v[t[2]].y() - oy, cz = v[t[2]].z() - oz;
        volume += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    }
    return volume;
}

// Per thread, reused over calls.
struct Scratch {
    StampedMarks colliding, vertex, triangle;
};
Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

struct SideResult {
    double area = k_undefined;
    double depth = k_undefined;
};

// Object x's surface inside the closed object y, for each region of the object pair.
class SurfaceInside {
public:
    SurfaceInside(const Frame& frame, std::uint32_t x, std::uint32_t y, std::span<const TrianglePair> pairs,
         std::span<const Piece> pieces, std::span<const std::uint32_t> regions, std::span<Region> all)
        : m_frame(frame), m_x(x), m_y(y), m_pairs(pairs), m_pieces(pieces) {
        const ObjectFrame& xo = frame.objects[x];
        m_scratch.colliding.next(xo.triangle_count());
        for (const std::uint32_t r : regions) {
            for (const std::uint32_t i : all[r].pair_indices) m_scratch.colliding.mark(tri_x(pairs[i]));
        }
        m_shape = mesh_shape(*xo.topology);
        // Y's faces point out of it when its signed volume is positive.
        const ObjectFrame& yo = frame.objects[y];
        m_outward = signed_volume(yo) >= 0 ? 1.0 : -1.0;
    }

    SideResult measure(const Region& region) {
        const ObjectFrame& xo = m_frame.objects[m_x];
        const ObjectFrame& yo = m_frame.objects[m_y];
        m_scratch.vertex.next(xo.topology->vertex_count);
        m_scratch.triangle.next(xo.triangle_count());
        std::vector<std::uint32_t> by_triangle(region.pair_indices);
        std::sort(by_triangle.begin(), by_triangle.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return tri_x(m_pairs[a]) < tri_x(m_pairs[b]); });
        double area = 0;
        std::vector<std::uint32_t> inside;  // X's vertices inside Y, in the order reached
        std::vector<std::uint32_t> from;    // per inside vertex: the one the flood came from (none: k_none)
        std::vector<std::uint32_t> seed_face;  // per inside vertex the walk found: a near face of Y
        constexpr std::uint32_t k_none = UINT32_MAX;
        const auto reach = [&](std::uint32_t v, std::uint32_t parent, std::uint32_t face) {
            if (!m_scratch.vertex.mark(v)) return;
            inside.push_back(v);
            from.push_back(parent);
            seed_face.push_back(face);
        };
        std::vector<Oriented> segments;
        std::map<std::uint32_t, double> touching;  // triangles meeting Y without a segment: coplanar area
        for (std::size_t begin = 0; begin < by_triangle.size();) {
            const std::uint32_t tri = tri_x(m_pairs[by_triangle[begin]]);
            std::size_t end = begin;
            while (end < by_triangle.size() && tri_x(m_pairs[by_triangle[end]]) == tri) ++end;
            orient(xo, yo, tri, std::span(by_triangle).subspan(begin, end - begin), segments);
            const TriangleMeasure t = measure_triangle(xo, tri, segments, m_walk);
            if (segments.empty()) {
                // Touching Y only at points or in its plane: the rest of the triangle lies on
                // one side, which the flood finds (it counts the triangle, less the coplanar
                // part, when it reaches a corner, and goes no further through it).
                double coplanar = 0;
                for (std::size_t k = begin; k < end; ++k) coplanar += m_pieces[by_triangle[k]].area;
                touching.emplace(tri, coplanar);
            }
            area += t.inside_area;
            for (int k = 0; k < 3; ++k) {
                // A corner reached before keeps the witness found then.
                if (t.corners[k] != Status::Inside || m_scratch.vertex.marked(xo.topology->triangles[tri][k])) continue;
                // Its witness: the nearest of the faces of Y its triangle meets.
                const Vec3& corner = xo.vertices[xo.topology->triangles[tri][k]];
                std::uint32_t witness = tri_y(m_pairs[by_triangle[begin]]);
                double nearest = std::numeric_limits<double>::infinity();
                for (std::size_t j = begin; j < end; ++j) {
                    const std::uint32_t face = tri_y(m_pairs[by_triangle[j]]);
                    const double d = squared_distance(corner, face);
                    if (d < nearest) {
                        nearest = d;
                        witness = face;
                    }
                }
                reach(xo.topology->triangles[tri][k], k_none, witness);
            }
            begin = end;
        }
        // The flood: a triangle that meets nothing of Y and has a corner inside lies inside.
        for (std::size_t next = 0; next < inside.size(); ++next) {
            const std::uint32_t v = inside[next];
            for (std::uint32_t k = m_shape->incident_begin[v]; k < m_shape->incident_begin[v + 1]; ++k) {
                const std::uint32_t t = m_shape->incident[k];
                if (m_scratch.triangle.marked(t)) continue;
                const auto touch = touching.find(t);
                if (m_scratch.colliding.marked(t) && touch == touching.end()) continue;
                m_scratch.triangle.mark(t);
                const auto c = xo.corners(t);
                const double full = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
                if (touch != touching.end()) {
                    area += std::max(0.0, full - touch->second);
                    continue;
                }
                area += full;
                for (const std::uint32_t w : xo.topology->triangles[t]) reach(w, static_cast<std::uint32_t>(next), k_none);
            }
        }
        // The deepest. Seeded by the vertex the flood reached last (farthest from the curves),
        // then in flood order, each vertex with an upper bound on its distance to Y: its
        // distance to a witness face of Y (for a corner of a crossed triangle, the nearest of
        // the faces that triangle meets; for a vertex the flood reached, its parent's witness,
        // or the face its own search found). Only a vertex whose bound exceeds the deepest so
        // far is searched, and that search stops at the first triangle within the deepest (the
        // distance to it is again an upper bound); it starts from the bound, skipping every node
        // of the tree farther than that.
        double depth = 0;
        if (!inside.empty()) {
            if (!m_distance) m_distance.emplace(*yo.topology, yo.vertices.span());
            depth = (*m_distance)(xo.vertices[inside.back()]);
            std::vector<std::uint32_t> witness(inside.size());
            for (std::size_t k = 0; k < inside.size(); ++k) {
                const Vec3& v = xo.vertices[inside[k]];
                witness[k] = from[k] == k_none ? seed_face[k] : witness[from[k]];
                double bound = std::sqrt(squared_distance(v, witness[k]));
                if (bound > depth) {
                    std::uint32_t nearer = witness[k];
                    const double searched = m_distance->beyond(v, depth, &nearer, bound);
                    if (searched < bound) {
                        bound = searched;
                        witness[k] = nearer;
                    }
                }
                depth = std::max(depth, bound);
            }
        }
        return {area, depth};
    }

private:
    // The squared distance from p to face `face` of Y.
    double squared_distance(const Vec3& p, std::uint32_t face) const {
        const auto f = m_frame.objects[m_y].corners(face);
        return (closest_point_on_triangle(p, f[0], f[1], f[2]) - p).squaredNorm();
    }

    std::uint32_t tri_x(const TrianglePair& p) const { return m_x == p.obj_a ? p.tri_a : p.tri_b; }
    std::uint32_t tri_y(const TrianglePair& p) const { return m_x == p.obj_a ? p.tri_b : p.tri_a; }

    // Segments reported with the same two ends' keys: their weights and border changes
    // summed in the keys' order (first key's end, second key's end), and how many.
    struct Shared {
        double weight = 0, first_change = 0, second_change = 0;
        int count = 0;
    };

    // The segments of triangle `tri`'s pairs `indices`, oriented, each once.
    void orient(const ObjectFrame& xo, const ObjectFrame& yo, std::uint32_t tri, std::span<const std::uint32_t> indices,
                std::vector<Oriented>& out) {
        out.clear();
        const TriIndices& ids = xo.topology->triangles[tri];
        const auto c = xo.corners(tri);
        const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
        // A triangle has a handful of segments: a short list, searched, not a map per triangle
        // (kept from triangle to triangle, as `found` is).
        std::vector<std::pair<std::pair<EndKey, EndKey>, Shared>>& shared = m_shared;
        shared.clear();
        const auto group_of = [&](const std::pair<EndKey, EndKey>& keys) -> Shared& {
            for (auto& [k, group] : shared) {
                if (k == keys) return group;
            }
            return shared.emplace_back(keys, Shared{}).second;
        };
        std::vector<Oriented>& found = m_found;
        found.clear();
        for (const std::uint32_t i : indices) {
            const Piece& piece = m_pieces[i];
            if (piece.kind != PairIntersection::Kind::Segment) continue;
            const auto f = yo.corners(tri_y(m_pairs[i]));
            const Vec3 direction = normal.cross(m_outward * (f[1] - f[0]).cross(f[2] - f[0]));
            const double along = (piece.ends[1] - piece.ends[0]).dot(direction);
            if (along == 0) continue;
            Oriented s{piece.ends[0], piece.ends[1], piece.keys[0], piece.keys[1]};
            if (along < 0) {
                std::swap(s.from, s.to);
                std::swap(s.from_key, s.to_key);
            }
            // +1 outside F's plane, -1 inside, 0 on it: orient3d(F, c[k]), as the intersection
            // decided it.
            const std::array<std::int8_t, 3>& sides = m_x == m_pairs[i].obj_a ? piece.sides_a : piece.sides_b;
            const auto side = [&](int k) { return -m_outward * sides[k]; };
            const auto change = [&](double position, double fallback) {
                const int corner = static_cast<int>(position);
                const bool at_corner = position == corner;
                const double before = side(at_corner ? (corner + 2) % 3 : corner % 3), after = side((corner + 1) % 3);
                return before != 0 && after != 0 ? (before - after) / 2 : fallback;
            };
            s.from_position = border_position(s.from_key, m_x, ids, c, s.from);
            s.to_position = border_position(s.to_key, m_x, ids, c, s.to);
            if (s.from_position) s.from_change = change(*s.from_position, -1);
            if (s.to_position) s.to_change = change(*s.to_position, 1);
            if (s.from_key.valid && s.to_key.valid) {
                const bool forward = s.from_key < s.to_key;
                Shared& group = group_of(forward ? std::pair(s.from_key, s.to_key) : std::pair(s.to_key, s.from_key));
                if (group.count++ == 0) found.push_back(s);
                group.weight += forward ? 1 : -1;
                group.first_change += forward ? s.from_change : s.to_change;
                group.second_change += forward ? s.to_change : s.from_change;
            } else {
                found.push_back(s);
            }
        }
        for (Oriented& s : found) {
            if (s.from_key.valid && s.to_key.valid) {
                // The faces reporting it, net, as seen in this copy's direction.
                const bool forward = s.from_key < s.to_key;
                const Shared& group = group_of(forward ? std::pair(s.from_key, s.to_key) : std::pair(s.to_key, s.from_key));
                s.weight = (forward ? group.weight : -group.weight) / group.count;
                s.from_change = (forward ? group.first_change : group.second_change) / group.count;
                s.to_change = (forward ? group.second_change : group.first_change) / group.count;
            }
            if (s.weight != 0 || s.from_change != 0 || s.to_change != 0) out.push_back(s);
        }
    }

    const Frame& m_frame;
    std::uint32_t m_x, m_y;
    std::span<const TrianglePair> m_pairs;
    std::span<const Piece> m_pieces;
    Scratch& m_scratch = scratch();
    std::shared_ptr<const MeshShape> m_shape;
    double m_outward = 1;
    std::optional<SurfaceDistance> m_distance;
    // Working arrays of orient and measure_triangle, kept from triangle to triangle.
    std::vector<std::pair<std::pair<EndKey, EndKey>, Shared>> m_shared;
    std::vector<Oriented> m_found;
    BorderWalk m_walk;
};

}  // namespace

void measure_penetration(const Frame& frame, std::span<const TrianglePair> pairs, std::span<const Piece> pieces,
                         std::span<Region> regions) {
    // The regions of each object pair (regions are ordered by their first pair, not by objects).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> by_objects;
    for (std::uint32_t r = 0; r < regions.size(); ++r) {
        Region& region = regions[r];
        region.depth = region.inside_area_a = region.inside_area_b = k_undefined;
        if (region.obj_a != region.obj_b) by_objects[{region.obj_a, region.obj_b}].push_back(r);
    }
    for (const auto& [objects, members] : by_objects) {
        const auto [a, b] = objects;
        for (const bool a_inside_b : {true, false}) {
            const std::uint32_t x = a_inside_b ? a : b, y = a_inside_b ? b : a;
            if (!mesh_shape(*frame.objects[y].topology)->closed) continue;
            SurfaceInside side(frame, x, y, pairs, pieces, members, regions);
            for (const std::uint32_t r : members) {
                const SideResult measured = side.measure(regions[r]);
                (a_inside_b ? regions[r].inside_area_a : regions[r].inside_area_b) = measured.area;
                Region& region = regions[r];
                region.depth = std::isnan(region.depth) ? measured.depth : std::max(region.depth, measured.depth);
            }
        }
    }
}

}  // namespace collidescope::regions
