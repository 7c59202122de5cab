// Surface patches: the boundary loops, bottom-up over the tree, and the per-frame test.
//
// A boundary chain is a sorted list of edges (lo < hi by vertex index) with a coefficient:
// +1 for lo -> hi, -1 for hi -> lo. A leaf's chain sums its triangles' three edges; an
// inner node's is the sum of its children's, so edges shared by consistently oriented
// triangles cancel. A coefficient outside {-1, 0, 1} (edges of inconsistent orientation,
// more than two triangles) or a repeated index in a triangle leaves the node without a loop.

#include "bvh/surface_patches.hpp"

#include "collidescope/geometry.hpp"
#include "geometry/simple_loop.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <span>
#include <cmath>

namespace collidescope::bvh {
namespace {

struct ChainEdge {
    std::uint32_t lo = 0, hi = 0;
    int coef = 0;
};

bool key_less(const ChainEdge& a, const ChainEdge& b) { return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi); }
bool same_key(const ChainEdge& a, const ChainEdge& b) { return a.lo == b.lo && a.hi == b.hi; }

struct Chain {
    std::vector<ChainEdge> edges;
    bool valid = false;
};

/// Sums the edges of edges[begin..) with equal keys, in place (they are sorted), dropping
/// zeros and truncating the vector; false when a coefficient leaves {-1, 0, 1}.
bool coalesce(std::vector<ChainEdge>& edges, std::size_t begin) {
    std::size_t write = begin;
    for (std::size_t r = begin; r < edges.size(); ++r) {
        if (write > begin && same_key(edges[write - 1], edges[r])) {
            edges[write - 1].coef += edges[r].coef;
            if (edges[write - 1].coef == 0) --write;
            else if (std::abs(edges[write - 1].coef) > 1) return false;
        } else {
            edges[write++] = edges[r];
        }
    }
    edges.resize(write);
    return true;
}

/// The sum of two chains (each sorted and coalesced).
Chain merged(const Chain& a, const Chain& b) {
    Chain chain;
    if (!a.valid || !b.valid) return chain;
    chain.edges.resize(a.edges.size() + b.edges.size());
    std::merge(a.edges.begin(), a.edges.end(), b.edges.begin(), b.edges.end(), chain.edges.begin(), key_less);
    chain.valid = coalesce(chain.edges, 0);
    return chain;
}

/// Appends the chain's loop to `out` when the chain is exactly one closed loop through
/// distinct vertices; returns its length, or 0. With the edges sorted by source (S) and by
/// destination (D), one loop means every vertex is the source of one edge and the destination
/// of one, so the k-th smallest source equals the k-th smallest destination; the edge after
/// S[i] then is S[k] where D[k] is S[i]: a walk without searching.
std::uint32_t append_loop(std::span<const ChainEdge> edges, std::vector<std::uint32_t>& out) {
    const std::size_t m = edges.size();
    if (m < 3) return 0;
    thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> by_source;  // (from, to); scratch
    thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> by_target;  // (to, index in by_source)
    thread_local std::vector<std::uint32_t> after;                               // index in by_source -> next
    by_source.clear();
    for (const ChainEdge& e : edges) by_source.emplace_back(e.coef > 0 ? e.lo : e.hi, e.coef > 0 ? e.hi : e.lo);
    std::sort(by_source.begin(), by_source.end());
    by_target.clear();
    for (std::uint32_t i = 0; i < m; ++i) by_target.emplace_back(by_source[i].second, i);
    std::sort(by_target.begin(), by_target.end());
    after.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
        if (by_source[k].first != by_target[k].first) return 0;  // a vertex with two edges out or in
        if (k > 0 && by_source[k].first == by_source[k - 1].first) return 0;
        after[by_target[k].second] = static_cast<std::uint32_t>(k);
    }
    const std::size_t begin = out.size();
    std::uint32_t at = 0;
    for (std::size_t step = 0; step < m; ++step) {
        out.push_back(by_source[at].first);
        at = after[at];
        if (at == 0 && step + 1 < m) {  // closed early: more than one loop
            out.resize(begin);
            return 0;
        }
    }
    return static_cast<std::uint32_t>(m);
}

/// A lone triangle has no pairs: it keeps no loop.
constexpr std::uint32_t kMinPatch = 2;

std::size_t max_loop(std::uint32_t triangles) {
    return 16 + static_cast<std::size_t>(8.0 * std::sqrt(static_cast<double>(triangles)));
}

}  // namespace

namespace {

/// Records the loop of node i, whose chain `edges` was just fitted (valid), into `loops`
/// (offsets relative to that vector); false when the chain is too long to keep.
bool record_loop(std::size_t i, std::span<const ChainEdge> edges, SurfacePatches& p, std::vector<std::uint32_t>& loops) {
    if (edges.size() > max_loop(p.triangles[i])) return false;
    if (p.triangles[i] < kMinPatch) return true;
    p.loop_begin[i] = static_cast<std::uint32_t>(loops.size());
    p.loop_size[i] = append_loop(edges, loops);
    return true;
}

/// A top node (above the refit plan's subtrees): from its children's chains.
void fit_top_patch(const Tree& tree, std::size_t i, std::vector<Chain>& chains, SurfacePatches& p,
                   std::vector<std::uint32_t>& loops) {
    const Node& node = tree.nodes[i];
    p.triangles[i] = p.triangles[i + 1] + p.triangles[node.index];
    chains[i] = merged(chains[i + 1], chains[node.index]);
    chains[i + 1] = Chain{};
    chains[node.index] = Chain{};
    if (chains[i].valid && !record_loop(i, chains[i].edges, p, loops)) chains[i] = Chain{};
}

/// One refit subtree, children before parents (reverse preorder), with every chain in one
/// buffer used as a stack: reverse preorder finishes an inner node's left child last and its
/// right child just before the left subtree, so a node's two children are the two records on
/// top. No allocation per node (a vector per chain made the patches cost 3x the build).
/// Returns the subtree root's chain (the top nodes merge it).
Chain fit_subtree_patches(const Tree& tree, NodeRange nodes, SurfacePatches& p, std::vector<std::uint32_t>& loops) {
    struct Record {
        std::size_t begin;
        bool valid;
    };
    thread_local std::vector<ChainEdge> stack;
    thread_local std::vector<Record> records;
    stack.clear();
    records.clear();
    for (std::size_t i = nodes.end; i-- > nodes.root;) {
        const Node& node = tree.nodes[i];
        Record record{stack.size(), true};
        if (node.is_leaf()) {
            p.triangles[i] = node.count;
            const TriIndices* tris = tree.leaf_triangles.data() + node.index;
            for (std::uint32_t t = 0; t < node.count && record.valid; ++t)
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t u = tris[t][k], v = tris[t][(k + 1) % 3];
                    record.valid = record.valid && u != v;  // a degenerate triangle: no loop here or above
                    stack.push_back(u < v ? ChainEdge{u, v, 1} : ChainEdge{v, u, -1});
                }
            std::sort(stack.begin() + static_cast<std::ptrdiff_t>(record.begin), stack.end(), key_less);
        } else {
            const Record left = records.back();
            records.pop_back();
            const Record right = records.back();
            records.pop_back();
            p.triangles[i] = p.triangles[i + 1] + p.triangles[node.index];
            record = {right.begin, left.valid && right.valid};
            // The two records are adjacent and sorted: merge them where they lie.
            if (record.valid)
                std::inplace_merge(stack.begin() + static_cast<std::ptrdiff_t>(right.begin),
                                   stack.begin() + static_cast<std::ptrdiff_t>(left.begin), stack.end(), key_less);
        }
        record.valid = record.valid && coalesce(stack, record.begin);
        if (!record.valid) stack.resize(record.begin);
        const std::span<const ChainEdge> edges(stack.data() + record.begin, stack.size() - record.begin);
        if (record.valid && !record_loop(i, edges, p, loops)) {
            record.valid = false;
            stack.resize(record.begin);
        }
        records.push_back(record);
    }
    Chain root;
    root.valid = records.back().valid;
    root.edges.assign(stack.begin() + static_cast<std::ptrdiff_t>(records.back().begin), stack.end());
    return root;
}

}  // namespace

void build_surface_patches(Tree& tree) {
    SurfacePatches& p = tree.patches;
    const std::size_t n = tree.nodes.size();
    p.loop_vertices.clear();  // assign and clear keep whatever storage the patches have
    p.loop_begin.assign(n, 0);
    p.loop_size.assign(n, 0);
    p.triangles.assign(n, 0);
    p.sides.assign(n, 0);
    // The refit plan's subtrees in parallel (fit_subtree_patches), then its top nodes; loops go
    // to one vector per part, joined in plan order (deterministic), offsets shifted.
    const RefitPlan& plan = tree.refit_plan;
    std::vector<Chain> chains(n);
    std::vector<std::vector<std::uint32_t>> parts(plan.subtrees.size() + 1);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.subtrees.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
            const NodeRange nodes = plan.subtrees[s].nodes;
            chains[nodes.root] = fit_subtree_patches(tree, nodes, p, parts[s]);
        }
    });
    for (std::size_t k = plan.top.size(); k-- > 0;) fit_top_patch(tree, plan.top[k], chains, p, parts.back());
    for (std::size_t s = 0; s < parts.size(); ++s) {
        const auto offset = static_cast<std::uint32_t>(p.loop_vertices.size());
        if (s < plan.subtrees.size()) {
            for (std::uint32_t i = plan.subtrees[s].nodes.root; i < plan.subtrees[s].nodes.end; ++i)
                if (p.loop_size[i] != 0) p.loop_begin[i] += offset;
        } else {
            for (const std::uint32_t i : plan.top)
                if (p.loop_size[i] != 0) p.loop_begin[i] += offset;
        }
        p.loop_vertices.insert(p.loop_vertices.end(), parts[s].begin(), parts[s].end());
    }
}

bool surface_like(std::span<const TriIndices> triangles) {
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * triangles.size());
    for (const TriIndices& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t u = t[k], v = t[(k + 1) % 3];
            keys.push_back(u < v ? (u << 32 | v) : (v << 32 | u));
        }
    std::sort(keys.begin(), keys.end());
    std::size_t shared = 0;
    for (std::size_t k = 1; k < keys.size(); ++k) shared += keys[k] == keys[k - 1];
    return 2 * shared >= triangles.size();
}

bool patch_is_embedded(const Tree& tree, std::uint32_t node, std::span<const Vec3> vertices) {
    const SurfacePatches& p = tree.patches;
    const std::uint8_t sides = p.sides[node];
    if (sides == 0 || p.loop_size[node] == 0) return false;
    const std::span<const std::uint32_t> loop(p.loop_vertices.data() + p.loop_begin[node], p.loop_size[node]);
    for (int k = 0; k < 3; ++k) {
        if ((sides >> (2 * k)) & 3u) {
            if (contact::projected_loop_is_simple(loop, vertices, k)) return true;
        }
    }
    return false;
}

}  // namespace collidescope::bvh
