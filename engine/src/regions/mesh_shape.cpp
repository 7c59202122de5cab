// Closedness and vertex-triangle incidence of a topology, cached by revision: a deforming
// mesh keeps its topology over the frames, so the sort below runs once, not once a frame.

#include "mesh_shape.hpp"

#include <algorithm>
#include <mutex>
#include <utility>

namespace collidescope::regions {
namespace {

MeshShape compute(const Topology& topology) {
    MeshShape shape;
    const std::uint32_t vertices = topology.vertex_count;
    shape.incident_begin.assign(vertices + 1, 0);
    for (const TriIndices& t : topology.triangles) {
        for (const std::uint32_t v : t) ++shape.incident_begin[v + 1];
    }
    for (std::uint32_t v = 0; v < vertices; ++v) shape.incident_begin[v + 1] += shape.incident_begin[v];
    shape.incident.resize(shape.incident_begin[vertices]);
    detail::LargeVector<std::uint32_t> next(shape.incident_begin.begin(), shape.incident_begin.end() - 1);
    for (std::uint32_t tri = 0; tri < topology.triangles.size(); ++tri) {
        for (const std::uint32_t v : topology.triangles[tri]) shape.incident[next[v]++] = tri;
    }
    // Closed: each directed edge (u, v) once, and its reverse (v, u) once. Per vertex u, from
    // its incidence list: the corners after u in its triangles (its outgoing edges' ends) and
    // the corners before it (its incoming edges' starts). Closed exactly when, at every vertex,
    // neither list repeats a vertex and the two are the same set: (u, v) then appears once
    // (v once among u's outgoing ends) and (v, u) once (v once among u's incoming starts).
    // Sorting two short lists per vertex, where counting each edge by scanning both ends'
    // lists read each triangle some 24 times (the demo's first frame of regions: 0.3 ms of
    // grouping and closedness, now 0.2).
    if (topology.triangles.empty()) return shape;
    for (const TriIndices& t : topology.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return shape;
    }
    std::vector<std::uint32_t> out, in;
    for (std::uint32_t u = 0; u < vertices; ++u) {
        out.clear();
        in.clear();
        for (std::uint32_t k = shape.incident_begin[u]; k < shape.incident_begin[u + 1]; ++k) {
            const TriIndices& t = topology.triangles[shape.incident[k]];
            const int at = t[0] == u ? 0 : t[1] == u ? 1 : 2;
            out.push_back(t[(at + 1) % 3]);
            in.push_back(t[(at + 2) % 3]);
        }
        std::sort(out.begin(), out.end());
        std::sort(in.begin(), in.end());
        if (out != in || std::adjacent_find(out.begin(), out.end()) != out.end()) return shape;
    }
    shape.closed = true;
    return shape;
}

}  // namespace

std::shared_ptr<const MeshShape> mesh_shape(const Topology& topology) {
    // A few entries: the objects of the scenes in use. Revisions are unique in the process.
    static std::mutex mutex;
    static std::vector<std::pair<std::uint64_t, std::shared_ptr<const MeshShape>>> cache;
    constexpr std::size_t k_entries = 64;
    {
        const std::lock_guard lock(mutex);
        for (const auto& [revision, shape] : cache) {
            if (revision == topology.revision && topology.revision != 0) return shape;
        }
    }
    auto shape = std::make_shared<const MeshShape>(compute(topology));
    if (topology.revision == 0) return shape;  // no revision: not cacheable
    const std::lock_guard lock(mutex);
    if (cache.size() == k_entries) cache.erase(cache.begin());
    cache.emplace_back(topology.revision, shape);
    return shape;
}

}  // namespace collidescope::regions
