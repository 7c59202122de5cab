#pragma once
// Traversal (engine/src/bvh): tree-vs-tree for object pairs, self-traversal within one object,
// producing candidate triangle pairs (closed triangle boxes that overlap) for the exact test.
// What is done with a candidate is the narrow phase's business, not the traversal's.

#include "bvh/bvh.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace collidescope::bvh {

/// A thread's candidate pairs during a traversal: a buffer of some megabytes, grown once and
/// kept (TraversalBuffers), in large blocks (collidescope/large_blocks.hpp) so that it is shared
/// among threads and pipelines instead of each thread's malloc arena touching memory anew.
using CandidateBuffer = LargeVector<TrianglePair>;

/// One object's tree and mesh, as the traversal reads them (spans over the caller's memory).
struct MeshView {
    const Tree* tree = nullptr;
    std::span<const TriIndices> triangles;
    std::span<const Vec3> vertices;
    /// Optional marks (the hybrid framework's culled tree, thesis 4.3 step C): when set, a
    /// node whose alive_nodes entry is 0 and a triangle whose alive_triangles entry is 0 are
    /// skipped by tree-vs-tree traversal. Indexed by node and by triangle id.
    std::span<const std::uint8_t> alive_nodes;
    std::span<const std::uint8_t> alive_triangles;
};

/// Percolates triangle marks up `tree` (thesis 4.3 step C): a leaf is alive when one of its
/// triangles is, an inner node when one of its children is. Returns one entry per node.
std::vector<std::uint8_t> percolate_alive(const Tree& tree, std::span<const std::uint8_t> alive_triangles);

/// A unit of traversal work. obj_a < obj_b: node_a of A against node_b of B. obj_a == obj_b
/// and node_a == node_b: self-traversal below that node. obj_a == obj_b, node_a != node_b:
/// two disjoint subtrees of one object (the self rule's pairs i != j). With `wide`, obj_a !=
/// obj_b and the nodes are entries of the trees' wide layouts (wide_tree.hpp) whose boxes
/// are known to overlap: step_wide.
struct WorkItem {
    std::uint32_t obj_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t node_a = 0;
    std::uint32_t node_b = 0;
    bool wide = false;
};

/// What a traversal did. Counts do not depend on the thread count.
struct TraversalStats {
    double ms = 0;
    std::uint64_t nodes_visited = 0;    ///< node pairs tested plus self nodes entered
    std::uint64_t box_tests = 0;        ///< node-pair and triangle-pair box tests
    std::uint64_t candidate_pairs = 0;  ///< triangle pairs whose boxes overlap
    /// Triangles below self nodes proven embedded (surface_patches.hpp), their pairs skipped.
    std::uint64_t self_culled_triangles = 0;
    /// Box-overlapping pairs of one object sharing a vertex index that the traversal proved
    /// apart (geometry/adjacent_filter.hpp): not candidates.
    std::uint64_t adjacent_apart = 0;

    void add(const TraversalStats& other) {
        adjacent_apart += other.adjacent_apart;
        nodes_visited += other.nodes_visited;
        box_tests += other.box_tests;
        candidate_pairs += other.candidate_pairs;
        self_culled_triangles += other.self_culled_triangles;
    }
};

/// Options of the parallel traversal.
struct TraversalConfig {
    /// Work items are expanded breadth-first until at least this many exist, then run in
    /// parallel. A fixed number (not the thread count), so counts are thread-independent.
    std::uint32_t parallel_items = 256;
};

/// Processes one node-pair item: the box test, then leaf triangle pairs into `candidates` or
/// follow-up items onto `stack` (the larger node is split). traverse_pair.cpp.
void step_pair(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats);

/// Processes one wide item: four child boxes of one tree against a box of the other at a
/// time (one vector comparison), overlapping pairs onto `stack`; two leaves' triangle pairs
/// on their double boxes into `candidates` (objects differ: no adjacency, no alive marks).
/// Counts a wide item as a node visited and a vector test as four box tests. Both trees'
/// wide layouts must be fitted. traverse_wide.cpp.
void step_wide(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats);

/// Appends the root item of objects a and b (non-empty trees) to `roots`: the wide one when
/// a != b, both trees' wide layouts are fitted and no alive marks are set (none at all when
/// the roots' boxes do not overlap), else the binary one. traverse_wide.cpp.
void add_pair_root(std::uint32_t a, std::uint32_t b, std::span<const MeshView> meshes, std::vector<WorkItem>& roots);

/// Processes one self item (obj_a == obj_b, node_a == node_b): a leaf's own pairs i < j, or
/// the children's self items and their pair item. traverse_self.cpp.
void step_self(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats);

/// The per-thread stacks and candidate buffers of a traversal, kept by a caller that
/// traverses every frame so that they are reused: a fresh buffer of a million candidates a
/// frame costs its page faults again each time (a sixth of a rod pile's frame).
class TraversalBuffers;
std::shared_ptr<TraversalBuffers> make_traversal_buffers();

/// Runs `roots` to completion (in parallel, TBB) and appends every candidate pair, canonical,
/// in an unspecified order. `meshes` is indexed by object; items name only objects whose
/// tree is non-empty and fitted to the view's vertices. `buffers` (optional) are reused.
TraversalStats traverse(std::vector<WorkItem> roots, std::span<const MeshView> meshes,
                        const TraversalConfig& config, std::vector<TrianglePair>& candidates,
                        TraversalBuffers* buffers = nullptr);

}  // namespace collidescope::bvh
