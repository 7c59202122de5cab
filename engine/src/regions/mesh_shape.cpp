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
    // Closed: each directed edge (u, v) once, and its reverse (v, u) once. Through the
    // incidence lists: u's outgoing edges are the corners after u in its triangles.
    if (topology.triangles.empty()) return shape;
    for (const TriIndices& t : topology.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return shape;
    }
    const auto after = [&](std::uint32_t tri, std::uint32_t v) {
        const TriIndices& t = topology.triangles[tri];
        return t[0] == v ? t[1] : t[1] == v ? t[2] : t[0];
    };
    const auto count_edge = [&](std::uint32_t u, std::uint32_t v) {  // triangles with directed edge (u, v)
        int n = 0;
        for (std::uint32_t k = shape.incident_begin[u]; k < shape.incident_begin[u + 1]; ++k) n += after(shape.incident[k], u) == v;
        return n;
    };
    for (std::uint32_t u = 0; u < vertices; ++u) {
        for (std::uint32_t k = shape.incident_begin[u]; k < shape.incident_begin[u + 1]; ++k) {
            const std::uint32_t v = after(shape.incident[k], u);
            if (count_edge(u, v) != 1 || count_edge(v, u) != 1) return shape;
        }
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
