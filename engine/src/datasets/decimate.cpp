// Vertex-clustering decimation: cells, cluster means, surviving triangles, compaction.

#include "datasets/decimate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace collidescope::datasets {
namespace {

constexpr std::uint32_t k_unused = std::numeric_limits<std::uint32_t>::max();

// The cell of every vertex, as a cluster number (clusters numbered in vertex order).
std::vector<std::uint32_t> cluster_vertices(const std::vector<Vec3>& vertices,
                                            std::uint32_t cells) {
    Vec3 lo = vertices.front();
    Vec3 hi = vertices.front();
    for (const Vec3& v : vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double longest = std::max((hi - lo).maxCoeff(), std::numeric_limits<double>::min());
    const double per_cell = static_cast<double>(cells) / longest;
    std::unordered_map<std::uint64_t, std::uint32_t> cluster_of_cell;
    std::vector<std::uint32_t> cluster(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        std::uint64_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            // At most `cells` + 1 cells per axis (the top face of the box gets its own).
            const double offset = (vertices[i][axis] - lo[axis]) * per_cell;
            const auto c = static_cast<std::uint64_t>(std::floor(offset));
            key = key * (std::uint64_t{cells} + 2) + c;
        }
        const auto next = static_cast<std::uint32_t>(cluster_of_cell.size());
        cluster[i] = cluster_of_cell.try_emplace(key, next).first->second;
    }
    return cluster;
}

// The mean position of each cluster's vertices, summed in vertex order.
std::vector<Vec3> cluster_means(const std::vector<Vec3>& vertices,
                                const std::vector<std::uint32_t>& cluster) {
    const std::uint32_t count = *std::max_element(cluster.begin(), cluster.end()) + 1;
    std::vector<Vec3> sum(count, Vec3::Zero());
    std::vector<std::uint32_t> members(count, 0);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        sum[cluster[i]] += vertices[i];
        ++members[cluster[i]];
    }
    for (std::uint32_t c = 0; c < count; ++c) sum[c] /= static_cast<double>(members[c]);
    return sum;
}

std::uint64_t triangle_key(TriIndices t) {
    std::sort(t.begin(), t.end());
    return (std::uint64_t{t[0]} << 42) ^ (std::uint64_t{t[1]} << 21) ^ t[2];
}

}  // namespace

MeshData decimate(const MeshData& mesh, std::uint32_t cells) {
    assert(cells >= 1 && !mesh.vertices.empty());
    const std::vector<std::uint32_t> cluster = cluster_vertices(mesh.vertices, cells);
    const std::vector<Vec3> means = cluster_means(mesh.vertices, cluster);
    std::vector<std::uint32_t> new_index(means.size(), k_unused);
    std::unordered_set<std::uint64_t> seen;
    MeshData result;
    for (const TriIndices& triangle : mesh.triangles) {
        const TriIndices c = {cluster[triangle[0]], cluster[triangle[1]], cluster[triangle[2]]};
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
        // Cluster numbers stay below 2^21 for any mesh this is used on (asserted).
        assert(means.size() < (std::size_t{1} << 21));
        if (!seen.insert(triangle_key(c)).second) continue;
        TriIndices out{};
        for (int k = 0; k < 3; ++k) {
            if (new_index[c[k]] == k_unused) {
                new_index[c[k]] = static_cast<std::uint32_t>(result.vertices.size());
                result.vertices.push_back(means[c[k]]);
            }
            out[k] = new_index[c[k]];
        }
        result.triangles.push_back(out);
    }
    return result;
}

}  // namespace collidescope::datasets
