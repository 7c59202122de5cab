// Vertex-clustering decimation: valid, deterministic, and as coarse as asked.

#include "datasets/decimate.hpp"
#include "datasets/generated_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace collidescope::datasets {
namespace {

// A wavy (n x n)-vertex sheet over [0, 1]^2.
MeshData wavy_sheet(std::uint32_t n) {
    MeshData mesh;
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double x = static_cast<double>(i) / (n - 1), y = static_cast<double>(j) / (n - 1);
            mesh.vertices.emplace_back(x, y, 0.1 * std::sin(7 * x) * std::cos(5 * y));
        }
    }
    mesh.triangles = grid_triangles(n, n);
    return mesh;
}

void expect_valid(const MeshData& mesh) {
    std::set<std::array<std::uint32_t, 3>> seen;
    std::vector<bool> used(mesh.vertices.size(), false);
    for (const TriIndices& t : mesh.triangles) {
        for (const std::uint32_t v : t) {
            ASSERT_LT(v, mesh.vertices.size());
            used[v] = true;
        }
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
        TriIndices sorted = t;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_TRUE(seen.insert(sorted).second) << "duplicate triangle";
    }
    EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST(Decimate, FineCellsKeepTheMesh) {
    const MeshData sheet = wavy_sheet(9);
    // 64 cells along the unit side: every vertex (1/8 apart) has a cell of its own.
    // Vertices are renumbered in order of first use; triangles and positions stay.
    const MeshData same = decimate(sheet, 64);
    ASSERT_EQ(same.triangles.size(), sheet.triangles.size());
    EXPECT_EQ(same.vertices.size(), sheet.vertices.size());
    EXPECT_EQ(same.triangles[0], (TriIndices{0, 1, 2}));
    for (std::size_t t = 0; t < sheet.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(same.vertices[same.triangles[t][k]], sheet.vertices[sheet.triangles[t][k]]);
        }
    }
}

TEST(Decimate, CoarserCellsGiveFewerTriangles) {
    const MeshData sheet = wavy_sheet(41);
    std::size_t previous = sheet.triangles.size() + 1;
    for (const std::uint32_t cells : {64u, 20u, 10u, 5u}) {
        const MeshData coarse = decimate(sheet, cells);
        SCOPED_TRACE(cells);
        expect_valid(coarse);
        EXPECT_LT(coarse.triangles.size(), previous);
        EXPECT_GT(coarse.triangles.size(), 0u);
        previous = coarse.triangles.size();
    }
}

TEST(Decimate, IsDeterministic) {
    const MeshData sheet = wavy_sheet(33);
    const MeshData a = decimate(sheet, 7);
    const MeshData b = decimate(sheet, 7);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(Decimate, VerticesAreClusterMeans) {
    // Longest side 2 with 2 cells: unit cells. Vertices 0, 2 and 3 share cell (0, 0), so the
    // second triangle collapses; the first keeps three cells: (0, 0), (2, 0) and (2, 1).
    MeshData mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 0.25, 0), Vec3(0.75, 0.5, 0),
                     Vec3(2, 1.5, 0)};
    mesh.triangles = {{0, 1, 4}, {2, 1, 3}};
    const MeshData coarse = decimate(mesh, 2);
    ASSERT_EQ(coarse.triangles.size(), 1u);
    EXPECT_EQ(coarse.triangles[0], (TriIndices{0, 1, 2}));
    ASSERT_EQ(coarse.vertices.size(), 3u);
    EXPECT_EQ(coarse.vertices[0], Vec3(1.25 / 3, 0.75 / 3, 0));
    EXPECT_EQ(coarse.vertices[1], Vec3(2, 0, 0));
    EXPECT_EQ(coarse.vertices[2], Vec3(2, 1.5, 0));
}

}  // namespace
}  // namespace collidescope::datasets
