// The GL context behind Mode 2 and the replayer: both implementations (OSMesa, EGL) are made,
// load their entry points and render; the cull through EGL gives the same PCS and pairs as
// through OSMesa (and so as brute force); contexts of both kinds live in one process on
// several threads at once; --gl names parse; a backend that cannot be made says why.

#include "support/brute_reference.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/gl_context.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace collidescope {
namespace {

TEST(GlBackendNames, ParseAndPrint) {
    for (const GlBackend backend : {GlBackend::Auto, GlBackend::Osmesa, GlBackend::Egl}) {
        EXPECT_EQ(parse_gl_backend(gl_backend_name(backend)), backend);
    }
    EXPECT_THROW(parse_gl_backend("glx"), std::invalid_argument);
}

// Clears a 4x4 framebuffer object to a colour and reads it back through the context's own
// entry points: the loaded table reaches the implementation that made the context.
std::uint32_t clear_and_read(std::uint8_t red) {
    GLuint framebuffer = 0, colour = 0;
    glGenFramebuffers(1, &framebuffer);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glClearColor(float(red) / 255.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    std::uint32_t pixel = 0;
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &pixel);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &colour);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return pixel & 0xffu;
}

class EachBackend : public ::testing::TestWithParam<GlBackend> {};

TEST_P(EachBackend, MakesACurrentOpenGL45CoreContext) {
    const auto context = gl::make_gl_context(GetParam());
    EXPECT_EQ(context->backend(), GetParam());
    const std::string suffix = GetParam() == GlBackend::Egl ? " via EGL" : " via OSMesa";
    EXPECT_NE(context->renderer().find(suffix), std::string::npos) << context->renderer();
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    EXPECT_GE(major * 10 + minor, 45) << context->renderer();
    EXPECT_EQ(clear_and_read(200), 200u);
}

TEST_P(EachBackend, CullGivesTheOsmesaPcsAndTheBrutePairs) {
    Scene scene = make_builtin_scene("C:small");
    PipelineConfig reference_config;
    reference_config.method = "gpu";
    reference_config.gpu.gl = GlBackend::Osmesa;
    PipelineConfig config = reference_config;
    config.gpu.gl = GetParam();
    for (const GpuCullVariant variant : {GpuCullVariant::Queries, GpuCullVariant::Flags}) {
        reference_config.gpu.variant = config.gpu.variant = variant;
        Pipeline reference(reference_config);
        Pipeline pipeline(config);
        for (std::uint32_t f = 0; f < scene.source->frame_count(); f += 4) {
            const Frame frame = scene.source->frame(f);
            const FrameResult expected = reference.process(frame);
            const FrameResult got = pipeline.process(frame);
            ASSERT_TRUE(got.stats.gpu.has_value());
            EXPECT_EQ(got.stats.gpu->survivors, expected.stats.gpu->survivors) << "frame " << f;
            EXPECT_EQ(got.colliding_pairs, expected.colliding_pairs) << "frame " << f;
            EXPECT_EQ(got.colliding_pairs, testing::reference_colliding_pairs(frame, scene.self_collision))
                << "frame " << f;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, EachBackend, ::testing::Values(GlBackend::Osmesa, GlBackend::Egl),
                         [](const auto& param_info) { return std::string(gl_backend_name(param_info.param)); });

// OSMesa and EGL export the same GL symbols; each thread must reach its own context's.
TEST(GlContexts, BothKindsOnSeveralThreadsAtOnce) {
    std::vector<std::uint32_t> read(8, 0);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < read.size(); ++t) {
        threads.emplace_back([t, &read] {
            const auto context = gl::make_gl_context(t % 2 == 0 ? GlBackend::Osmesa : GlBackend::Egl);
            for (int repeat = 0; repeat < 20; ++repeat) {
                context->make_current();
                read[t] = clear_and_read(static_cast<std::uint8_t>(10 + 20 * t));
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    for (std::size_t t = 0; t < read.size(); ++t) EXPECT_EQ(read[t], 10 + 20 * t) << "thread " << t;
}

// Auto: EGL on a machine with a GPU, OSMesa without one.
TEST(GlContexts, AutoIsEglWithAGpuAndOsmesaWithout) {
    const GlBackend expected = gl::egl_hardware_device_present() ? GlBackend::Egl : GlBackend::Osmesa;
    EXPECT_EQ(gl::make_gl_context(GlBackend::Auto)->backend(), expected);
}

}  // namespace
}  // namespace collidescope
