// Data sets at the small preset against the thesis's descriptions (chapter 5), checked with
// an all-pairs exact count: which frames collide, and how much.

#include "scene_helpers.hpp"

#include "collidescope/geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

namespace collidescope::testing {
namespace {

constexpr std::uint64_t k_seed = 1;

struct SceneCounts {
    std::vector<CollisionCount> frames;
    std::uint64_t triangles = 0;

    std::uint64_t colliding(std::size_t f) const { return frames[f].colliding; }
    std::size_t colliding_frames() const {
        return static_cast<std::size_t>(std::count_if(
            frames.begin(), frames.end(), [](const CollisionCount& c) { return c.colliding > 0; }));
    }
    std::uint64_t most_colliding() const {
        std::uint64_t most = 0;
        for (const CollisionCount& c : frames) most = std::max(most, c.colliding);
        return most;
    }
};

// Every frame's counts, printed as one line so failures and logs show the whole story.
std::optional<SceneCounts> count_scene(const std::string& name, std::string& why) {
    std::optional<Scene> scene = try_make_scene(name, "small", k_seed, why);
    if (!scene) return std::nullopt;
    SceneCounts counts;
    std::cout << "[ counts   ] " << name << " small, colliding pairs per frame:";
    for (std::uint32_t f = 0; f < scene->source->frame_count(); ++f) {
        const Frame frame = scene->source->frame(f);
        if (f == 0) {
            for (const ObjectFrame& object : frame.objects) {
                counts.triangles += object.triangle_count();
            }
        }
        counts.frames.push_back(count_collisions(frame, scene->self_collision));
        std::cout << ' ' << counts.frames.back().colliding;
    }
    std::cout << '\n';
    return counts;
}

// Every triangle pair of `frame`, no prefilter: the reference for count_collisions.
std::uint64_t all_pairs_colliding(const Frame& frame, bool self_collision) {
    std::uint64_t colliding = 0;
    for (std::uint32_t oa = 0; oa < frame.objects.size(); ++oa) {
        for (std::uint32_t ob = oa; ob < frame.objects.size(); ++ob) {
            if (oa == ob && !self_collision) continue;
            const ObjectFrame& a = frame.objects[oa];
            const ObjectFrame& b = frame.objects[ob];
            for (std::uint32_t ta = 0; ta < a.triangle_count(); ++ta) {
                const std::array<Vec3, 3> pa = a.corners(ta);
                for (std::uint32_t tb = oa == ob ? ta + 1 : 0; tb < b.triangle_count(); ++tb) {
                    const std::array<Vec3, 3> pb = b.corners(tb);
                    colliding += oa == ob ? self_triangles_collide(a.topology->triangles[ta], pa,
                                                                   b.topology->triangles[tb], pb)
                                          : triangles_intersect(pa[0], pa[1], pa[2], pb[0],
                                                                pb[1], pb[2]);
                }
            }
        }
    }
    return colliding;
}

// The helper's sweep and box test lose no pair: the middle frame of A (inter-object) and the
// last of B (inter-object and self) against every pair.
TEST(Collisions, SweepCountsWhatAllPairsCount) {
    for (const char* name : {"A", "B"}) {
        std::string why;
        std::optional<Scene> scene = try_make_scene(name, "small", k_seed, why);
        ASSERT_TRUE(scene) << why;
        const std::uint32_t f = name[0] == 'A' ? scene->source->frame_count() / 2
                                               : scene->source->frame_count() - 1;
        const Frame frame = scene->source->frame(f);
        const std::uint64_t expected = all_pairs_colliding(frame, scene->self_collision);
        EXPECT_GT(expected, 0u) << name;
        EXPECT_EQ(count_collisions(frame, scene->self_collision).colliding, expected) << name;
    }
}

// A: rigid bunnies that pass through each other for part of the animation.
TEST(Collisions, BunniesMeetOnlyInTheMiddle) {
    std::string why;
    const std::optional<SceneCounts> counts = count_scene("A", why);
    ASSERT_TRUE(counts) << why;
    const std::size_t last = counts->frames.size() - 1;
    EXPECT_EQ(counts->colliding(0), 0u);
    EXPECT_EQ(counts->colliding(last), 0u);
    EXPECT_GT(counts->colliding(last / 2), 0u);
    EXPECT_LT(counts->colliding_frames(), counts->frames.size() / 2);
}

// B: cloths that start apart and then deform into each other with many true collisions.
TEST(Collisions, ClothsStartApartThenCollideMuch) {
    std::string why;
    const std::optional<SceneCounts> counts = count_scene("B", why);
    ASSERT_TRUE(counts) << why;
    EXPECT_EQ(counts->colliding(0), 0u);
    EXPECT_GE(counts->colliding_frames(), counts->frames.size() / 2);
    EXPECT_GE(counts->most_colliding(), counts->triangles / 20);
}

// B's cloths fold onto themselves at the end: self-collisions that only the self rule finds.
TEST(Collisions, ClothsCollideWithThemselvesAtTheEnd) {
    std::string why;
    std::optional<Scene> scene = try_make_scene("B", "small", k_seed, why);
    ASSERT_TRUE(scene) << why;
    ASSERT_TRUE(scene->self_collision);
    const Frame first = scene->source->frame(0);
    EXPECT_EQ(count_collisions(first, true).colliding, 0u);
    const Frame last = scene->source->frame(scene->source->frame_count() - 1);
    EXPECT_GT(count_collisions(last, true).colliding, count_collisions(last, false).colliding);
}

// C: sheets in very close proximity: many near misses, few true collisions, some frames none.
TEST(Collisions, SineSheetsNearlyMissAlways) {
    std::string why;
    const std::optional<SceneCounts> counts = count_scene("C", why);
    ASSERT_TRUE(counts) << why;
    EXPECT_GT(counts->colliding_frames(), 0u);
    EXPECT_LT(counts->colliding_frames(), counts->frames.size());
    EXPECT_LE(counts->most_colliding(), counts->triangles / 50);
    for (const CollisionCount& frame : counts->frames) {
        EXPECT_GE(frame.box_overlaps, counts->triangles);
    }
}

// D: an incoherent, overlapping first half; coherent tori that never touch in the second.
TEST(Collisions, BartSoupOverlapsThenAssemblesApart) {
    std::string why;
    const std::optional<SceneCounts> counts = count_scene("D", why);
    ASSERT_TRUE(counts) << why;
    const std::size_t half = counts->frames.size() / 2;
    EXPECT_GT(counts->colliding(0), 0u);
    std::size_t soup_colliding = 0;
    for (std::size_t f = 0; f < half; ++f) soup_colliding += counts->colliding(f) > 0;
    EXPECT_GE(soup_colliding, half / 2);
    for (std::size_t f = half; f < counts->frames.size(); ++f) {
        EXPECT_EQ(counts->colliding(f), 0u) << "frame " << f;
    }
}

// E: the two dragons collide in every frame, intact and exploding.
class ExplodingDragons : public ::testing::TestWithParam<std::string> {};

TEST_P(ExplodingDragons, CollideThroughout) {
    std::string why;
    const std::optional<SceneCounts> counts = count_scene(GetParam(), why);
    ASSERT_TRUE(counts) << why;
    EXPECT_EQ(counts->colliding_frames(), counts->frames.size());
}

INSTANTIATE_TEST_SUITE_P(Speeds, ExplodingDragons, ::testing::Values("E1", "E2", "E3", "E4"),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace collidescope::testing
