// RegionTracker over a plane moving through a torus's underside: one region (both loops
// through the same triangles), then two (a split), then one again (a merge), then none; ids,
// predecessors, split_from and merged_into say so. And a region that moves keeps its id, and
// matching by boxes equals the obvious scan on hundreds of regions.

#include "regions/region_shapes.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace collidescope {
namespace {

using namespace testing;

struct Step {
    Frame frame;
    std::vector<TrianglePair> pairs;
    std::vector<Region> regions;
};

Step step(const MeshData& a, const MeshData& b) {
    Step s{make_frame({a, b}), {}, {}};
    s.pairs = pairs_of(s.frame, false);
    s.regions = find_regions(s.frame, s.pairs);
    return s;
}

TEST(RegionTracker, SplitAndMergeAreRecorded) {
    const MeshData ring = torus(48, 12, 2.0, 0.5);
    RegionTracker tracker;
    std::vector<std::vector<Region>> frames;
    for (const double z : {-0.6, -0.46, -0.36, -0.46, -0.6}) {
        Step s = step(ring, plane_at(z, 3.0, 30));
        tracker.update(static_cast<std::uint32_t>(frames.size()), s.regions);
        frames.push_back(std::move(s.regions));
    }
    ASSERT_EQ(frames[0].size(), 0u);
    ASSERT_EQ(frames[1].size(), 1u);
    EXPECT_EQ(frames[1][0].loops, 2u);  // both loops in one region: they share vertices
    ASSERT_EQ(frames[2].size(), 2u);
    ASSERT_EQ(frames[3].size(), 1u);
    ASSERT_EQ(frames[4].size(), 0u);

    const std::uint32_t first = frames[1][0].id;
    EXPECT_EQ(first, 1u);
    // The split: one part keeps the id, the other starts a track split from it.
    const std::uint32_t a = frames[2][0].id, b = frames[2][1].id;
    EXPECT_TRUE((a == first) != (b == first)) << a << ' ' << b;
    const std::uint32_t other = a == first ? b : a;
    ASSERT_EQ(tracker.tracks().size(), 2u);
    EXPECT_EQ(tracker.tracks()[other - 1].split_from, first);
    for (const Region& region : frames[2]) EXPECT_EQ(region.predecessors, std::vector<std::uint32_t>{first});
    // The merge: one id goes on, the other ends merged into it.
    const Region& merged = frames[3][0];
    EXPECT_EQ(merged.predecessors.size(), 2u);
    const std::uint32_t ended = merged.id == first ? other : first;
    EXPECT_EQ(tracker.tracks()[ended - 1].merged_into, merged.id);
    EXPECT_EQ(tracker.tracks()[ended - 1].last_frame, 2u);
    const RegionTrack& kept = tracker.tracks()[merged.id - 1];
    EXPECT_EQ(kept.last_frame, 3u);
    EXPECT_GT(kept.max_curve_length, 0.0);
}

TEST(RegionTracker, AMovingContactKeepsItsIdAndItsLargestLength) {
    RegionTracker tracker;
    const MeshData fixed = sphere(32, 16, Vec3(0, 0, 0), 1.0);
    std::vector<double> lengths;
    for (std::uint32_t f = 0; f < 6; ++f) {
        Step s = step(fixed, sphere(29, 15, Vec3(1.9 - 0.15 * f, 0.01 * f, 0.02), 1.0));
        tracker.update(f, s.regions);
        ASSERT_EQ(s.regions.size(), 1u) << f;
        EXPECT_EQ(s.regions[0].id, 1u) << f;
        lengths.push_back(s.regions[0].curve_length);
    }
    ASSERT_EQ(tracker.tracks().size(), 1u);
    const RegionTrack& track = tracker.tracks()[0];
    EXPECT_EQ(track.first_frame, 0u);
    EXPECT_EQ(track.last_frame, 5u);
    EXPECT_EQ(track.frames, 6u);
    const auto largest = std::max_element(lengths.begin(), lengths.end());
    EXPECT_DOUBLE_EQ(track.max_curve_length, *largest);
    EXPECT_EQ(track.max_curve_length_frame, static_cast<std::uint32_t>(largest - lengths.begin()));
}

// A gap in the frames breaks every track: nothing continues across it.
TEST(RegionTracker, AGapStartsNewTracks) {
    RegionTracker tracker;
    const MeshData fixed = sphere(24, 12, Vec3(0, 0, 0), 1.0);
    Step s = step(fixed, sphere(23, 11, Vec3(1.5, 0, 0.01), 1.0));
    tracker.update(0, s.regions);
    tracker.update(5, s.regions);
    EXPECT_EQ(s.regions[0].id, 2u);
    EXPECT_TRUE(s.regions[0].predecessors.empty());
}

// Matching by boxes against the obvious scan: hundreds of regions of one object pair in two
// frames, sharing no triangle (as data set E's fragments), with random boxes of random sizes,
// a few very wide and some touching exactly: each region's predecessors are exactly last
// frame's regions whose boxes meet its box, in last frame's order (all weigh the same).
TEST(RegionTracker, BoxMatchingFindsEveryOverlappingBoxOfLastFrame) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> at(-1, 1), size(0, 0.05);
        std::uint32_t next_triangle = 0;
        const auto frame_of = [&](std::size_t count) {
            std::vector<Region> regions(count);
            for (std::size_t r = 0; r < count; ++r) {
                Region& region = regions[r];
                region.obj_a = 0;
                region.obj_b = 1;
                region.pairs = 1;
                region.triangles_a = {next_triangle};
                region.triangles_b = {next_triangle++};
                const Vec3 low(at(rng), at(rng), at(rng));
                Vec3 extent(size(rng), size(rng), size(rng));
                if (r % 97 == 0) extent.x() = 1.5;  // a few very wide boxes
                region.box = Eigen::AlignedBox3d(low, low + extent);
                if (r % 13 == 5 && r > 0) {  // touching the previous one's box exactly, along x
                    const Eigen::AlignedBox3d& before = regions[r - 1].box;
                    region.box = Eigen::AlignedBox3d(Vec3(before.max().x(), before.min().y(), before.min().z()),
                                                     Vec3(before.max().x() + 0.01, before.max().y(), before.max().z()));
                }
            }
            return regions;
        };
        RegionTracker tracker;
        std::vector<Region> last = frame_of(300);
        tracker.update(0, last);
        std::vector<Region> now = frame_of(300);
        // Some of this frame's boxes touch last frame's exactly too.
        for (std::size_t r = 7; r < now.size(); r += 29) {
            const Eigen::AlignedBox3d& before = last[r].box;
            now[r].box = Eigen::AlignedBox3d(Vec3(before.min().x() - 0.02, before.min().y(), before.min().z()),
                                             Vec3(before.min().x(), before.max().y(), before.max().z()));
        }
        tracker.update(1, now);
        std::size_t matched = 0;
        for (std::size_t r = 0; r < now.size(); ++r) {
            std::vector<std::uint32_t> expected;
            for (const Region& before : last) {
                if (before.box.intersects(now[r].box)) expected.push_back(before.id);
            }
            matched += expected.empty() ? 0 : 1;
            EXPECT_EQ(now[r].predecessors, expected) << "seed " << seed << ", region " << r;
        }
        EXPECT_GE(matched, 10u) << "the boxes meet often enough to test the matching";
    }
}

}  // namespace
}  // namespace collidescope
