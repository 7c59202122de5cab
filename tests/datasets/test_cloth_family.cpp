// The cloth family (issue 23) at the small preset: sizes, determinism, and what each scene
// is built to show, checked with the slow all-pairs count (scene_helpers).

#include "scene_helpers.hpp"

#include "collidescope/datasets.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace collidescope::testing {
namespace {

/// Colliding pairs per frame (self-collision on, as the scenes say), printed on one line.
std::vector<std::uint64_t> colliding_per_frame(const Scene& scene) {
    std::vector<std::uint64_t> colliding;
    std::cout << "[ counts   ] " << scene.name << " small, colliding pairs per frame:";
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        colliding.push_back(count_collisions(scene.source->frame(f), scene.self_collision).colliding);
        std::cout << ' ' << colliding.back();
    }
    std::cout << '\n';
    return colliding;
}

TEST(ClothFamily, SizesAndSelfCollision) {
    struct Size {
        const char* spec;
        std::uint64_t triangles;
        std::uint32_t frames;
    };
    for (const Size& size : {Size{"cloth-rest:small", 1'058, 4}, Size{"cloth-rest:large", 999'698, 8},
                             Size{"cloth-drape:small", 1'058 + 256, 6},
                             Size{"cloth-drape:large", 421'362 + 16'128, 10},
                             Size{"cloth-crumple:small", 1'034, 6},
                             Size{"cloth-crumple:large", 428'162, 10},
                             Size{"cloth-slide:small", 1'024, 6}, Size{"cloth-slide:large", 432'964, 10}}) {
        const Scene scene = make_builtin_scene(size.spec);
        EXPECT_TRUE(scene.self_collision) << size.spec;
        EXPECT_EQ(scene.source->frame_count(), size.frames) << size.spec;
        EXPECT_EQ(triangle_count(scene.source->frame(0)), size.triangles) << size.spec;
    }
}

TEST(ClothFamily, Deterministic) {
    for (const char* spec : {"cloth-rest:small", "cloth-drape:small", "cloth-crumple:small", "cloth-slide:small"}) {
        const Scene a = make_builtin_scene(spec), b = make_builtin_scene(spec);
        const std::uint32_t last = a.source->frame_count() - 1;
        EXPECT_EQ(hash_frame(a.source->frame(last)), hash_frame(b.source->frame(last))) << spec;
    }
}

TEST(ClothFamily, RestingClothIsFlatAndNeverCollides) {
    const Scene scene = make_builtin_scene("cloth-rest:small");
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);  // a range-for over a temporary's member dangles
        for (const Vec3& v : frame.objects[0].vertices) ASSERT_EQ(v.z(), static_cast<double>(0.3f)) << "frame " << f;
    }
    for (std::uint64_t c : colliding_per_frame(scene)) EXPECT_EQ(c, 0u);
}

TEST(ClothFamily, CrumplingStripNeverCollides) {
    for (std::uint64_t c : colliding_per_frame(make_builtin_scene("cloth-crumple:small"))) EXPECT_EQ(c, 0u);
}

TEST(ClothFamily, DrapeTouchesTheSphereOnlyAtTheEnd) {
    const std::vector<std::uint64_t> colliding = colliding_per_frame(make_builtin_scene("cloth-drape:small"));
    EXPECT_EQ(colliding.front(), 0u);
    EXPECT_GT(colliding.back(), 0u);
}

TEST(ClothFamily, SlidingSheetsOverlapInEveryFrame) {
    const Scene scene = make_builtin_scene("cloth-slide:small");
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f)
        EXPECT_EQ(scene.source->frame(f).objects[0].vertices[5].z(),
                  scene.source->frame(f).objects[1].vertices[7].z());  // one plane
    for (std::uint64_t c : colliding_per_frame(scene)) EXPECT_GT(c, 0u);
}

}  // namespace
}  // namespace collidescope::testing
