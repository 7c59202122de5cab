// Every method against brute force on the contact family (issue 37, small preset), at 1, 2 and
// 4 threads: the same pairs on every frame, and the exact test's expensive fallbacks under one
// in ten exact tests.

#include "support/ci.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace collidescope {
namespace {

struct MethodRun {
    std::vector<std::vector<TrianglePair>> pairs;
    std::uint64_t exact_tests = 0;
    std::uint64_t exact_fallbacks = 0;
};

MethodRun run(const Scene& scene, const std::string& method, int threads) {
    PipelineConfig config;
    config.method = method;
    config.self_collision = scene.self_collision;
    config.threads = threads;
    Pipeline pipeline(config);
    MethodRun out;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        FrameResult result = pipeline.process(scene.source->frame(f));
        out.exact_tests += result.stats.counts.exact_tests;
        out.exact_fallbacks += result.stats.counts.exact_fallbacks;
        out.pairs.push_back(std::move(result.colliding_pairs));
    }
    return out;
}

class ContactFamilyMethods : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactFamilyMethods, EveryMethodEqualsBruteAtOneTwoAndFourThreads) {
    const Scene scene = make_builtin_scene(GetParam() + ":small");
    const MethodRun reference = run(scene, "brute", 1);
    for (const std::string& method : method_names()) {
        if (method == "brute") continue;
        for (const int threads : {1, 2, 4}) {
            SCOPED_TRACE(method + " at " + std::to_string(threads) + " threads");
            MethodRun got;
            try {
                got = run(scene, method, threads);
            } catch (const UnavailableError& error) {
                COLLIDESCOPE_SKIP_OR_FAIL_UNDER_CI(std::string("no GL context: ") + error.what());
            }
            ASSERT_EQ(got.pairs.size(), reference.pairs.size());
            for (std::size_t f = 0; f < got.pairs.size(); ++f) EXPECT_EQ(got.pairs[f], reference.pairs[f]) << "frame " << f;
            EXPECT_LT(10 * got.exact_fallbacks, got.exact_tests + 1) << got.exact_fallbacks << " of " << got.exact_tests;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SmallPreset, ContactFamilyMethods,
                         ::testing::Values("contact-layers", "contact-spheres", "contact-rods", "contact-rollers",
                                           "coplanar-stack"));

}  // namespace
}  // namespace collidescope
