// Static meshes read through assimp are welded per mesh (mesh/weld.hpp): an STL file, whose
// triangles carry their own corners, comes back with shared vertices, so two triangles that
// share an edge do not count as colliding under the self-collision rule, while a real
// crossing still does (checked against the brute-force reference on the welded mesh).

#include "mesh/temp_files.hpp"
#include "support/brute_reference.hpp"

#include "collidescope/mesh.hpp"
#include "collidescope/scene.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

using testing_files::TempDir;
using testing_files::write_text;

std::string stl_facet(const std::array<Vec3, 3>& corners) {
    std::string text = "facet normal 0 0 0\nouter loop\n";
    for (const Vec3& c : corners) {
        text += "vertex " + std::to_string(c.x()) + " " + std::to_string(c.y()) + " " + std::to_string(c.z()) + "\n";
    }
    return text + "endloop\nendfacet\n";
}

Frame single_frame(const MeshData& mesh) {
    auto source = make_memory_source({"mesh"}, {{mesh}});
    return source->frame(0);
}

TEST(AssimpWeld, StlCornersBecomeSharedVerticesAndNeighboursStopColliding) {
    TempDir dir;
    // Two triangles sharing the edge (1,0,0)-(0,1,0), plus a third that pierces the first.
    const std::string text = "solid s\n" + stl_facet({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) +
                             stl_facet({Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) +
                             stl_facet({Vec3(0.25, 0.25, -1), Vec3(0.25, 0.25, 1), Vec3(0.3, 0.2, 1)}) + "endsolid s\n";
    write_text(dir / "s.stl", text);
    const MeshData mesh = read_mesh_file(dir / "s.stl");
    ASSERT_EQ(mesh.triangles.size(), 3u);
    EXPECT_EQ(mesh.vertices.size(), 7u);  // 9 corners, the shared edge's two welded
    EXPECT_EQ(mesh.triangles[0][1], mesh.triangles[1][0]);
    EXPECT_EQ(mesh.triangles[0][2], mesh.triangles[1][2]);
    const std::vector<TrianglePair> pairs = testing::reference_colliding_pairs(single_frame(mesh), true);
    // Only the piercing: (0, 2). Unwelded, (0, 1) touched along their edge and counted too.
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].tri_a, 0u);
    EXPECT_EQ(pairs[0].tri_b, 2u);
}

}  // namespace
}  // namespace collidescope
