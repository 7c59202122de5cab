// The contact family (issue 37) at the small preset: sizes, determinism, and what each scene
// is built to show, checked with the slow all-pairs count (scene_helpers): near contact where
// boxes overlap far more often than triangles touch, and coplanar overlap.

#include "scene_helpers.hpp"

#include "collidescope/datasets.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace collidescope::testing {
namespace {

/// The all-pairs counts of every frame (self-collision on, as the scenes say), printed.
std::vector<CollisionCount> counts_per_frame(const Scene& scene) {
    std::vector<CollisionCount> counts;
    std::cout << "[ counts   ] " << scene.name << " " << scene.preset << ", box overlaps / colliding per frame:";
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        counts.push_back(count_collisions(scene.source->frame(f), scene.self_collision));
        std::cout << ' ' << counts.back().box_overlaps << '/' << counts.back().colliding;
    }
    std::cout << '\n';
    return counts;
}

constexpr const char* k_scenes[] = {"contact-layers", "contact-spheres", "contact-rods", "contact-rollers",
                                    "coplanar-stack"};

TEST(ContactFamily, SizesAndSelfCollision) {
    struct Size {
        const char* spec;
        std::uint64_t triangles;
        std::uint32_t frames;
    };
    for (const Size& size : {Size{"contact-layers:small", 726 + 256, 5}, Size{"contact-layers:default", 58'806 + 4'096, 20},
                             Size{"contact-layers:large", 402'486 + 16'128, 8},
                             Size{"contact-spheres:small", 1'024, 5}, Size{"contact-spheres:large", 307'200, 8},
                             Size{"contact-rods:small", 1'656, 5}, Size{"contact-rods:large", 469'728, 8},
                             Size{"contact-rollers:small", 576 + 448, 5}, Size{"contact-rollers:large", 250'000 + 127'360, 8},
                             Size{"coplanar-stack:small", 968, 5}, Size{"coplanar-stack:large", 456'968, 8}}) {
        const Scene scene = make_builtin_scene(size.spec);
        EXPECT_TRUE(scene.self_collision) << size.spec;
        EXPECT_EQ(scene.source->frame_count(), size.frames) << size.spec;
        EXPECT_EQ(triangle_count(scene.source->frame(0)), size.triangles) << size.spec;
    }
}

TEST(ContactFamily, Deterministic) {
    for (const char* name : k_scenes) {
        const std::string spec = std::string(name) + ":small";
        const Scene a = make_builtin_scene(spec), b = make_builtin_scene(spec);
        const std::uint32_t last = a.source->frame_count() - 1;
        EXPECT_EQ(hash_frame(a.source->frame(last)), hash_frame(b.source->frame(last))) << spec;
    }
}

// Near contact: in every frame many more triangle pairs overlap as boxes than touch, which
// is what makes these scenes hard (a box test passes, the exact test says no).
TEST(ContactFamily, NearContactScenesOverlapAsBoxesFarMoreThanTheyTouch) {
    for (const char* name : {"contact-layers", "contact-spheres", "contact-rods", "contact-rollers"}) {
        for (const CollisionCount& count : counts_per_frame(make_builtin_scene(std::string(name) + ":small"))) {
            EXPECT_GT(count.box_overlaps, 4 * count.colliding + 100) << name;
        }
    }
}

// The layers' moving dent pushes the outer layer through the two below it: real contact,
// in every frame, besides the near contact everywhere else.
TEST(ContactFamily, TheDentPiercesTheLayersInEveryFrame) {
    for (const CollisionCount& count : counts_per_frame(make_builtin_scene("contact-layers:small"))) {
        EXPECT_GT(count.colliding, 0u);
    }
}

// Coplanar patches overlapping pairwise: many colliding pairs in every frame.
TEST(ContactFamily, CoplanarPatchesOverlapInEveryFrame) {
    const Scene scene = make_builtin_scene("coplanar-stack:small");
    for (const CollisionCount& count : counts_per_frame(scene)) EXPECT_GT(count.colliding, 100u);
    for (const ObjectFrame& object : scene.source->frame(2).objects) {
        for (const Vec3& vertex : object.vertices) ASSERT_EQ(vertex.z(), static_cast<double>(0.1f));
    }
}

}  // namespace
}  // namespace collidescope::testing
