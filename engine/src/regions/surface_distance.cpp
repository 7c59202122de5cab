// Nearest-triangle search: a stack of nodes, the nearer child first, skipping every node
// whose box lies farther than the best distance so far (squared distances throughout).

#include "surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

namespace collidescope::regions {
namespace {

double squared_box_distance(const bvh::Aabb& box, const Vec3& p) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = p[k] < box.lo[k] ? box.lo[k] - p[k] : p[k] > box.hi[k] ? p[k] - box.hi[k] : 0.0;
        sum += d * d;
    }
    return sum;
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0)) {  // a degenerate triangle: the nearest of its three edges' closest points
        Vec3 best = a;
        for (const auto& [s, t] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
            const Vec3 st = t - s;
            const double length = st.squaredNorm();
            const double u = length > 0 ? std::clamp((p - s).dot(st) / length, 0.0, 1.0) : 0.0;
            const Vec3 q = s + u * st;
            if ((q - p).squaredNorm() < (best - p).squaredNorm()) best = q;
        }
        return best;
    }
    return a + ab * (vb / sum) + ac * (vc / sum);
}

// Trees by topology revision, each out of the cache while a SurfaceDistance uses it (a second
// user of the same topology at once builds its own). A few entries: the objects in use.
class TreeCache {
public:
    std::unique_ptr<bvh::Tree> take(std::uint64_t revision) {
        const std::lock_guard lock(m_mutex);
        for (auto it = m_entries.begin(); it != m_entries.end(); ++it) {
            if (it->first == revision) {
                std::unique_ptr<bvh::Tree> tree = std::move(it->second);
                m_entries.erase(it);
                return tree;
            }
        }
        return nullptr;
    }
    void give(std::uint64_t revision, std::unique_ptr<bvh::Tree> tree) {
        const std::lock_guard lock(m_mutex);
        if (m_entries.size() == k_entries) m_entries.erase(m_entries.begin());
        m_entries.emplace_back(revision, std::move(tree));
    }

private:
    static constexpr std::size_t k_entries = 16;
    std::mutex m_mutex;
    std::vector<std::pair<std::uint64_t, std::unique_ptr<bvh::Tree>>> m_entries;
};

TreeCache& tree_cache() {
    static TreeCache cache;
    return cache;
}

SurfaceDistance::SurfaceDistance(const Topology& topology, std::span<const Vec3> vertices)
    : m_revision(topology.revision), m_triangles(topology.triangles), m_vertices(vertices) {
    if (m_revision != 0) m_tree = tree_cache().take(m_revision);
    if (m_tree) {
        bvh::refit(*m_tree, m_triangles, vertices);
    } else {
        m_tree = std::make_unique<bvh::Tree>();
        if (!m_triangles.empty()) bvh::build_tree(m_triangles, vertices, bvh::BuildConfig{}, *m_tree);
    }
}

SurfaceDistance::~SurfaceDistance() {
    if (m_revision != 0 && m_tree) tree_cache().give(m_revision, std::move(m_tree));
}

double SurfaceDistance::beyond(const Vec3& p, double bound, std::uint32_t* nearest_face, double known) const {
    // Squared: the nearest so far, from `known` on (nodes farther than it are skipped at once).
    double best = known * known;
    std::uint32_t best_face = UINT32_MAX;
    const double enough = bound > 0 ? bound * bound : -1;  // squared: a triangle this near ends the search
    if (best <= enough || m_tree->empty()) return known;
    thread_local std::vector<std::uint32_t> stack;  // kept: a search is short, an allocation was a fifth of it
    stack.assign(1, 0);
    while (!stack.empty()) {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        const bvh::Node& node = m_tree->nodes[index];
        if (squared_box_distance(node.box, p) > best) continue;
        if (node.is_leaf()) {
            for (std::uint32_t k = node.index; k < node.index + node.count; ++k) {
                const std::uint32_t face = m_tree->triangle_ids[k];
                const TriIndices& t = m_triangles[face];
                const Vec3 q = closest_point_on_triangle(p, m_vertices[t[0]], m_vertices[t[1]], m_vertices[t[2]]);
                if ((q - p).squaredNorm() < best) {
                    best = (q - p).squaredNorm();
                    best_face = face;
                }
            }
            if (best <= enough) break;
            continue;
        }
        const std::uint32_t left = index + 1, right = node.index;  // preorder: the left child is next
        const bool left_first = squared_box_distance(m_tree->nodes[left].box, p) < squared_box_distance(m_tree->nodes[right].box, p);
        stack.push_back(left_first ? right : left);
        stack.push_back(left_first ? left : right);
    }
    if (best_face == UINT32_MAX) return known;  // nothing nearer than `known`
    if (nearest_face) *nearest_face = best_face;
    return std::sqrt(best);
}

}  // namespace collidescope::regions
