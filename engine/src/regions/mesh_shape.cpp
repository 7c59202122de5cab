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
    std::vector<std::uint32_t> next(shape.incident_begin.begin(), shape.incident_begin.end() - 1);
    for (std::uint32_t tri = 0; tri < topology.triangles.size(); ++tri) {
        for (const std::uint32_t v : topology.triangles[tri]) shape.incident[next[v]++] = tri;
    }
    // Closed: the directed edges, sorted, hold each (u, v) once and its reverse once.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(3 * topology.triangles.size());
    bool degenerate = topology.triangles.empty();
    for (const TriIndices& t : topology.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) degenerate = true;
        for (int k = 0; k < 3; ++k) edges.emplace_back(t[k], t[(k + 1) % 3]);
    }
    if (degenerate) return shape;
    std::sort(edges.begin(), edges.end());
    bool closed = std::adjacent_find(edges.begin(), edges.end()) == edges.end();
    for (std::size_t k = 0; closed && k < edges.size(); ++k) {
        closed = std::binary_search(edges.begin(), edges.end(), std::pair(edges[k].second, edges[k].first));
    }
    shape.closed = closed;
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
