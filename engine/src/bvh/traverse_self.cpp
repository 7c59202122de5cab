// Self-traversal step (self-collision within one object): a node whose triangles are proven
// embedded this frame (surface_patches.hpp: one-way normals and a simple contour) has no
// pairs; otherwise its pairs are its children's own pairs plus the pairs between the two
// children. Every other box-overlapping pair i < j goes to the narrow phase, except adjacent
// pairs (sharing a vertex index) that adjacent_apart proves apart with certified signs; the
// exact self rule (self_triangles_collide) decides the rest, since sharing a vertex does not
// prove two triangles apart (DESIGN.md).

#include "bvh/surface_patches.hpp"
#include "bvh/traverse.hpp"
#include "geometry/adjacent_filter.hpp"

namespace collidescope::bvh {
namespace {

void leaf_self(const WorkItem& item, const MeshView& mesh, const Node& leaf,
               CandidateBuffer& candidates, TraversalStats& stats) {
    const std::uint32_t* ids = mesh.tree->triangle_ids.data() + leaf.index;
    const Aabb* boxes = mesh.tree->leaf_boxes.data() + leaf.index;
    const TriIndices* tris = mesh.tree->leaf_triangles.data() + leaf.index;
    for (std::uint32_t i = 0; i < leaf.count; ++i) {
        for (std::uint32_t j = i + 1; j < leaf.count; ++j) {
            ++stats.box_tests;
            if (!overlaps(boxes[i], boxes[j])) continue;
            if (filter::adjacent_apart(tris[i], tris[j], mesh.vertices.data())) {
                ++stats.adjacent_apart;
                continue;
            }
            candidates.push_back(make_pair_ordered(item.obj_a, ids[i], item.obj_a, ids[j]));
            ++stats.candidate_pairs;
        }
    }
}

}  // namespace

void step_self(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
               CandidateBuffer& candidates, TraversalStats& stats) {
    const MeshView& mesh = meshes[item.obj_a];
    const Node& node = mesh.tree->nodes[item.node_a];
    ++stats.nodes_visited;
    const Tree& tree = *mesh.tree;
    // A lone triangle has no pairs to skip.
    if (!tree.patches.empty() && tree.patches.triangles[item.node_a] > 1 &&
        patch_is_embedded(tree, item.node_a, mesh.vertices)) {
        stats.self_culled_triangles += tree.patches.triangles[item.node_a];
        return;
    }
    if (node.is_leaf()) {
        leaf_self(item, mesh, node, candidates, stats);
        return;
    }
    const std::uint32_t left = item.node_a + 1;
    const std::uint32_t right = node.index;
    stack.push_back({item.obj_a, item.obj_a, left, right});
    stack.push_back({item.obj_a, item.obj_a, right, right});
    stack.push_back({item.obj_a, item.obj_a, left, left});
}

}  // namespace collidescope::bvh
