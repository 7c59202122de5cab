// Segments to curves: a graph whose nodes are the segment ends' keys and whose edges are the
// segments, walked from every node that is not a simple joint (degree 2), then around what is
// left, which can only be loops. Its arrays, as long as the segments, are large blocks once
// they are large, as find_regions' working arrays are (why: find_regions.cpp).

#include "curves.hpp"

#include "first_seen.hpp"

#include "collidescope/large_blocks.hpp"

#include <algorithm>
#include <utility>
#include <span>

namespace collidescope::regions {
namespace {

struct Incidence {
    std::uint32_t segment;  ///< index into the region's segments
    std::uint32_t end;      ///< 0 or 1
};

using detail::LargeVector;

struct Graph {
    LargeVector<const Piece*> segments;
    LargeVector<std::array<std::uint32_t, 2>> nodes_of;  ///< per segment, the node of each end
    /// Node k's segment ends are ends[node_begin[k] .. node_begin[k + 1]) (one array, not a
    /// vector per node: a dense region has a node per segment).
    LargeVector<std::uint32_t> node_begin;
    LargeVector<Incidence> ends;

    std::size_t nodes() const { return node_begin.size() - 1; }
    std::span<const Incidence> incident(std::uint32_t node) const {
        return {ends.data() + node_begin[node], node_begin[node + 1] - node_begin[node]};
    }
};

Graph build_graph(std::span<const Piece> pieces, std::span<const std::uint32_t> indices) {
    Graph graph;
    struct Entry {
        std::uint64_t hash;
        std::uint32_t segment, end;
    };
    LargeVector<Entry> entries;
    for (const std::uint32_t index : indices) {
        const Piece& piece = pieces[index];
        if (piece.kind != PairIntersection::Kind::Segment) continue;
        const auto segment = static_cast<std::uint32_t>(graph.segments.size());
        graph.segments.push_back(&piece);
        for (std::uint32_t end = 0; end < 2; ++end) entries.push_back({key_hash(piece.keys[end]), segment, end});
    }
    const auto key = [&](const Entry& e) -> const EndKey& { return graph.segments[e.segment]->keys[e.end]; };
    // Nodes in the order of their first end; a key without a feature joins nothing (a node of
    // its own). Then each node's ends, in order, in one array.
    FirstSeen seen(entries.size());
    LargeVector<std::uint32_t> node_of(entries.size());
    LargeVector<std::uint32_t> counts;
    for (std::uint32_t i = 0; i < entries.size(); ++i) {
        const EndKey& k = key(entries[i]);
        const std::uint32_t first =
            k.valid ? seen.find_or_add(entries[i].hash, i, [&](std::uint32_t j) { return key(entries[j]) == k; }) : i;
        if (first == i) {
            node_of[i] = static_cast<std::uint32_t>(counts.size());
            counts.push_back(0);
        } else {
            node_of[i] = node_of[first];
        }
        ++counts[node_of[i]];
    }
    graph.node_begin.resize(counts.size());
    std::uint32_t start = 0;
    for (std::size_t node = 0; node < counts.size(); ++node) {
        graph.node_begin[node] = start;
        start += std::exchange(counts[node], graph.node_begin[node]);  // counts become fill positions
    }
    graph.nodes_of.resize(graph.segments.size());
    graph.ends.resize(entries.size());
    for (std::uint32_t i = 0; i < entries.size(); ++i) {
        graph.ends[counts[node_of[i]]++] = {entries[i].segment, entries[i].end};
        graph.nodes_of[entries[i].segment][entries[i].end] = node_of[i];
    }
    graph.node_begin.push_back(static_cast<std::uint32_t>(entries.size()));
    return graph;
}

// Walks from `node` along `segment` until a node that is not a joint of two, or back to `node`.
IntersectionCurve walk(const Graph& graph, std::uint32_t node, Incidence first, std::vector<bool>& used) {
    IntersectionCurve curve;
    curve.points.push_back(graph.segments[first.segment]->ends[first.end]);
    Incidence step = first;
    const std::uint32_t start = node;
    for (;;) {
        used[step.segment] = true;
        const Piece& piece = *graph.segments[step.segment];
        const std::uint32_t far = 1 - step.end;
        curve.length += (piece.ends[far] - piece.ends[step.end]).norm();
        const std::uint32_t next_node = graph.nodes_of[step.segment][far];
        const std::span<const Incidence> around = graph.incident(next_node);
        if (next_node == start && around.size() == 2) {
            curve.closed = true;
            break;
        }
        curve.points.push_back(piece.ends[far]);
        if (around.size() != 2) break;
        const Incidence next = around[0].segment == step.segment && around[0].end == far ? around[1] : around[0];
        if (used[next.segment]) break;
        step = next;
    }
    return curve;
}

}  // namespace

std::vector<IntersectionCurve> chain_curves(std::span<const Piece> pieces, std::span<const std::uint32_t> indices) {
    const Graph graph = build_graph(pieces, indices);
    std::vector<bool> used(graph.segments.size(), false);
    std::vector<IntersectionCurve> curves;
    for (std::uint32_t node = 0; node < graph.nodes(); ++node) {
        if (graph.incident(node).size() == 2) continue;
        for (const Incidence& incidence : graph.incident(node)) {
            if (!used[incidence.segment]) curves.push_back(walk(graph, node, incidence, used));
        }
    }
    for (std::uint32_t segment = 0; segment < graph.segments.size(); ++segment) {
        if (!used[segment]) curves.push_back(walk(graph, graph.nodes_of[segment][0], {segment, 0}, used));
    }
    return curves;
}

}  // namespace collidescope::regions
