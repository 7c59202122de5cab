// GpuCullConfig::depth_every: the cull reads back each triangle-level view's depth buffer after
// its forward pass. Where nothing is drawn the depth is 1; where a known triangle projects it is
// below 1 and maps back, through depth_near/depth_far, to that triangle's coordinate along the
// view axis. Capturing changes neither the PCS nor the pairs.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collidescope {
namespace {

PipelineConfig depth_config(std::uint32_t depth_every) {
    PipelineConfig config;
    config.method = "gpu";
    config.gpu.resolution = 64;
    config.gpu.views = {2};          // one view, along z
    config.gpu.view_matrix = false;  // keep it
    config.gpu.adaptive_p = false;   // the PCS does not depend on measured times
    config.gpu.depth_every = depth_every;
    return config;
}

// The depth at world (x, y) of a z view fitted to bounds [lo, hi] in x and y (pixel rows from
// the bottom, u = x, v = y for the z axis).
float depth_at(const GpuDepthImage& image, double x, double y, const Vec3& lo, const Vec3& hi) {
    const auto px = static_cast<std::uint32_t>((x - lo.x()) / (hi.x() - lo.x()) * image.width);
    const auto py = static_cast<std::uint32_t>((y - lo.y()) / (hi.y() - lo.y()) * image.height);
    return image.depth.at(std::size_t{py} * image.width + px);
}

// A lower sheet on [0,1]^2 at z = 0 and an upper one on [0.5,1.5]^2 at z = 0.01 whose x = 0.5
// column dips to z = 0 (so they touch and both stay in the PCS down to the triangle level). The
// corner x > 1, y < 0.5 is empty.
TEST(DepthCapture, EmptyPixelsAreOneAndDrawnPixelsMapToTheirTriangle) {
    const MeshData lower = testing::grid_sheet(8, 1.0);
    MeshData upper = testing::translated(testing::grid_sheet(8, 1.0), Vec3(0.5, 0.5, 0.01));
    for (std::size_t i = 0; i < upper.vertices.size(); i += 9) upper.vertices[i].z() = 0;  // x = 0.5 column
    const Frame frame = testing::make_frame({lower, upper});
    Pipeline pipeline(depth_config(1));
    const FrameResult result = pipeline.process(frame);
    ASSERT_TRUE(result.stats.gpu.has_value());
    const std::vector<GpuDepthImage>& images = result.stats.gpu->depth_images;
    ASSERT_EQ(images.size(), 1u);
    const GpuDepthImage& image = images[0];
    EXPECT_EQ(image.level, 1);
    EXPECT_EQ(image.view, 2);
    ASSERT_EQ(image.width, 64u);
    ASSERT_EQ(image.height, 64u);
    ASSERT_EQ(image.depth.size(), 64u * 64u);
    // The view fits every PCS triangle: x in [0, 1.5], y in [0, 1.5], z in [0, 0.01].
    const Vec3 lo(0, 0, 0), hi(1.5, 1.5, 0.01);
    EXPECT_LT(image.depth_near, 0.0);
    EXPECT_GT(image.depth_far, 0.01);
    EXPECT_EQ(depth_at(image, 1.3, 0.2, lo, hi), 1.0f);   // nothing drawn
    EXPECT_EQ(depth_at(image, 0.02, 1.45, lo, hi), 1.0f); // nothing drawn
    const auto world = [&](float depth) { return image.depth_near + depth * (image.depth_far - image.depth_near); };
    const float on_lower = depth_at(image, 0.25, 0.25, lo, hi);
    const float on_upper = depth_at(image, 1.3, 1.3, lo, hi);
    EXPECT_GE(on_lower, 0.0f);
    EXPECT_LT(on_lower, 1.0f);
    EXPECT_GE(on_upper, 0.0f);
    EXPECT_LT(on_upper, 1.0f);
    EXPECT_NEAR(world(on_lower), 0.0, 1e-4);   // the lower sheet's z
    EXPECT_NEAR(world(on_upper), 0.01, 1e-4);  // the upper sheet's z
    std::size_t empty = 0;
    for (const float d : image.depth) empty += d == 1.0f ? 1 : 0;
    EXPECT_GT(empty, 64u * 64u / 10);  // the empty corners: a quarter, less the conservative margins
    EXPECT_LT(empty, 64u * 64u / 2);
}

// Same frames with and without capture: the same survivors and pairs; images only on the
// frames whose index is a multiple of depth_every, one per triangle-level view.
TEST(DepthCapture, CaptureChangesNeitherThePcsNorThePairs) {
    const Scene scene = make_builtin_scene("C:small");
    PipelineConfig off = depth_config(0);
    PipelineConfig on = depth_config(3);
    off.gpu.views = on.gpu.views = {2, 0, 1};
    Pipeline without(off);
    Pipeline with(on);
    std::size_t captured = 0;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); f += 2) {
        const Frame frame = scene.source->frame(f);
        const FrameResult a = without.process(frame);
        const FrameResult b = with.process(frame);
        ASSERT_EQ(a.colliding_pairs, b.colliding_pairs) << "frame " << f;
        ASSERT_TRUE(a.stats.gpu && b.stats.gpu);
        EXPECT_EQ(a.stats.gpu->survivors, b.stats.gpu->survivors) << "frame " << f;
        EXPECT_TRUE(a.stats.gpu->depth_images.empty());
        std::size_t triangle_views = 0;
        for (const GpuViewInfo& view : b.stats.gpu->views) triangle_views += view.level == 1 ? 1 : 0;
        EXPECT_EQ(b.stats.gpu->depth_images.size(), frame.index % 3 == 0 ? triangle_views : 0) << "frame " << f;
        for (const GpuDepthImage& image : b.stats.gpu->depth_images) {
            EXPECT_EQ(image.depth.size(), 64u * 64u);
            for (const float d : image.depth) ASSERT_TRUE(d >= 0.0f && d <= 1.0f) << d;
        }
        captured += b.stats.gpu->depth_images.size();
    }
    EXPECT_GT(captured, 0u);  // the scene reaches the triangle level on captured frames
}

}  // namespace
}  // namespace collidescope
