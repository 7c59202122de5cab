// The building blocks of generated scenes: the random stream, float32 rounding, grid, torus
// and soup topologies, and the on-demand FrameSource with its topology phases.

#include "datasets/generated_source.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace collidescope::datasets {
namespace {

TEST(Random, MatchesTheSplitMix64ReferenceStream) {
    // Reference outputs of SplitMix64 from state 0 (Vigna's splitmix64.c).
    Random random(0);
    EXPECT_EQ(random.next_u64(), 0xE220A8397B1DCDAFULL);
    EXPECT_EQ(random.next_u64(), 0x6E789E6AA1B965F4ULL);
    EXPECT_EQ(random.next_u64(), 0x06C45D188009454FULL);
}

TEST(Random, StreamsOfOneSeedDiffer) {
    Random a(7, 1);
    Random b(7, 2);
    EXPECT_NE(a.next_u64(), b.next_u64());
}

TEST(Random, DrawsStayInTheirRanges) {
    Random random(3);
    double lo = 1, hi = 0;
    for (int i = 0; i < 10000; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        lo = std::min(lo, u);
        hi = std::max(hi, u);
        ASSERT_NEAR(random.unit_vector().norm(), 1.0, 1e-12);
        ASSERT_LE(random.in_ball(0.5).norm(), 0.5);
    }
    EXPECT_LT(lo, 0.01);  // the draws cover the range, not a corner of it
    EXPECT_GT(hi, 0.99);
}

TEST(RoundToFloat, RoundsToNearestFloat32) {
    const Vec3 p(0.1, -1.0 / 3.0, 1e-40);
    const Vec3 r = round_to_float32(p);
    EXPECT_EQ(r.x(), static_cast<double>(0.1f));
    EXPECT_EQ(r.y(), static_cast<double>(-1.0f / 3.0f));
    EXPECT_NE(r.x(), p.x());
    EXPECT_EQ(r.z(), 0x1.16c2p-133);  // a float32 subnormal
}

TEST(Topologies, GridHasTwoTrianglesPerCell) {
    const std::vector<TriIndices> grid = grid_triangles(4, 3);
    ASSERT_EQ(grid.size(), 2u * 3 * 2);
    EXPECT_EQ(grid[0], (TriIndices{0, 1, 5}));
    EXPECT_EQ(grid[1], (TriIndices{0, 5, 4}));
    for (const TriIndices& t : grid) {
        for (const std::uint32_t v : t) EXPECT_LT(v, 12u);
    }
}

TEST(Topologies, TorusIsClosedEveryVertexInSixTriangles) {
    const std::vector<TriIndices> torus = torus_triangles(5, 4);
    ASSERT_EQ(torus.size(), 2u * 5 * 4);
    std::map<std::uint32_t, int> uses;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const TriIndices& t : torus) {
        for (int k = 0; k < 3; ++k) {
            ++uses[t[k]];
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    }
    EXPECT_EQ(uses.size(), 20u);
    for (const auto& [vertex, count] : uses) EXPECT_EQ(count, 6) << "vertex " << vertex;
    for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);  // closed: no boundary
}

TEST(Topologies, SoupSharesNoVertex) {
    const std::vector<TriIndices> soup = soup_triangles(3);
    EXPECT_EQ(soup, (std::vector<TriIndices>{{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}));
}

// One object: a triangle for frames 0-1, a two-triangle soup from frame 2 on.
std::shared_ptr<FrameSource> two_phase_source() {
    GeneratedObject object;
    object.name = "thing";
    object.phases = {{0, make_topology({{0, 1, 2}}, 3)},
                     {2, make_topology(soup_triangles(2), 6)}};
    object.vertices = [](std::uint32_t frame, std::span<Vec3> out) {
        for (std::size_t v = 0; v < out.size(); ++v) {
            out[v] = Vec3(0.1 * frame, static_cast<double>(v), 1.0 / 3.0);
        }
    };
    std::vector<GeneratedObject> objects;
    objects.push_back(std::move(object));
    return make_generated_source(std::move(objects), 4);
}

TEST(GeneratedSource, HandsOutPhasesSharedAndRounded) {
    const std::shared_ptr<FrameSource> source = two_phase_source();
    ASSERT_EQ(source->frame_count(), 4u);
    ASSERT_EQ(source->object_count(), 1u);
    EXPECT_EQ(source->object_name(0), "thing");
    const Frame f0 = source->frame(0), f1 = source->frame(1), f2 = source->frame(2),
                f3 = source->frame(3);
    EXPECT_EQ(f0.objects[0].topology, f1.objects[0].topology);
    EXPECT_EQ(f2.objects[0].topology, f3.objects[0].topology);
    EXPECT_NE(f1.objects[0].topology->revision, f2.objects[0].topology->revision);
    EXPECT_EQ(f1.objects[0].vertices.size(), 3u);
    EXPECT_EQ(f3.objects[0].vertices.size(), 6u);
    EXPECT_EQ(f3.index, 3u);
    const Vec3 rounded(static_cast<double>(0.3f), 5, static_cast<double>(1.0f / 3.0f));
    EXPECT_EQ(f3.objects[0].vertices[5], rounded);
    EXPECT_THROW(source->frame(4), std::out_of_range);
}

TEST(GeneratedSource, RevisionsAreNeverReused) {
    std::set<std::uint64_t> revisions;
    for (int i = 0; i < 100; ++i) revisions.insert(make_topology({{0, 1, 2}}, 3)->revision);
    EXPECT_EQ(revisions.size(), 100u);
    EXPECT_EQ(revisions.count(0), 0u);
}

}  // namespace
}  // namespace collidescope::datasets
