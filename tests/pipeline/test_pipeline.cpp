// Pipeline::process against the all-pairs reference, its stats, its sinks, and the method
// registry.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace collidescope {
namespace {

// Keeps a copy of what each report held.
class RecordingSink final : public TraceSink {
public:
    void on_frame(const FrameReport& report) override {
        frames.push_back(report.frame.index);
        stats.push_back(report.stats);
        pairs.emplace_back(report.colliding_pairs.begin(), report.colliding_pairs.end());
    }
    std::vector<std::uint32_t> frames;
    std::vector<FrameStats> stats;
    std::vector<std::vector<TrianglePair>> pairs;
};

TEST(Pipeline, MatchesReferenceOnRandomScenes) {
    std::uint64_t culled_object_pairs = 0;
    for (const bool self_collision : {false, true}) {
        for (std::uint64_t seed = 100; seed < 140; ++seed) {
            SCOPED_TRACE("seed " + std::to_string(seed) + (self_collision ? ", self" : ""));
            const Scene scene = testing::random_scene(seed, {5, 3, 30, 4});
            Pipeline pipeline({"brute", self_collision, 0});
            for (const Frame& frame : testing::all_frames(scene)) {
                const FrameResult result = pipeline.process(frame);
                ASSERT_EQ(result.colliding_pairs, testing::reference_colliding_pairs(frame, self_collision))
                    << "frame " << frame.index;
                const std::uint64_t all_pairs = 5 * 4 / 2 + (self_collision ? 5 : 0);
                culled_object_pairs += all_pairs - result.stats.counts.object_pairs;
            }
        }
    }
    EXPECT_GT(culled_object_pairs, 0u);  // the object level did cull
}

TEST(Pipeline, FillsStatsAndReportsEveryFrameToEverySink) {
    const Scene scene = testing::random_scene(5, {3, 4, 20, 4});
    Pipeline pipeline({"brute", false, 0});
    RecordingSink first;
    RecordingSink second;
    pipeline.add_sink(first);
    pipeline.add_sink(second);
    std::vector<FrameResult> results;
    for (const Frame& frame : testing::all_frames(scene)) results.push_back(pipeline.process(frame));

    ASSERT_EQ(first.frames, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(second.frames, first.frames);
    for (std::size_t f = 0; f < results.size(); ++f) {
        const FrameStats& stats = first.stats[f];
        EXPECT_EQ(first.pairs[f], results[f].colliding_pairs);
        EXPECT_EQ(stats.frame, f);
        EXPECT_EQ(stats.method, "brute");
        EXPECT_EQ(stats.counts.colliding_pairs, results[f].colliding_pairs.size());
        EXPECT_EQ(stats.counts.exact_tests, stats.counts.candidate_pairs);
        EXPECT_GE(stats.counts.candidate_pairs, stats.counts.colliding_pairs);
        std::uint64_t triangles = 0;
        for (const ObjectFrame& object : scene.source->frame(static_cast<std::uint32_t>(f)).objects) {
            triangles += object.triangle_count();
        }
        EXPECT_EQ(stats.counts.triangles, triangles);
        EXPECT_GE(stats.ms.total, stats.ms.update + stats.ms.object_level + stats.ms.cull + stats.ms.narrow - 1e-9);
    }
}

TEST(Pipeline, ResultIsSortedAndCanonical) {
    const Scene scene = testing::random_scene(21, {4, 1, 40, 5});
    Pipeline pipeline({"brute", true, 0});
    const FrameResult result = pipeline.process(scene.source->frame(0));
    ASSERT_FALSE(result.colliding_pairs.empty());
    for (std::size_t k = 0; k < result.colliding_pairs.size(); ++k) {
        const TrianglePair& pair = result.colliding_pairs[k];
        EXPECT_LT(std::tie(pair.obj_a, pair.tri_a), std::tie(pair.obj_b, pair.tri_b));
        if (k > 0) {
            EXPECT_LT(result.colliding_pairs[k - 1], pair);
        }
    }
}

TEST(MethodRegistry, KnowsBruteAndRejectsUnknownNames) {
    const std::vector<std::string> names = method_names();
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.front(), "brute");
    for (const std::string& name : names) EXPECT_EQ(make_method(name)->name(), name);
    try {
        make_method("no-such-method");
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("brute"), std::string::npos) << error.what();
    }
}

TEST(Pipeline, RejectsBadConfig) {
    EXPECT_THROW(Pipeline({"no-such-method", false, 0}), std::invalid_argument);
    EXPECT_THROW(Pipeline({"brute", false, -1}), std::invalid_argument);
}

}  // namespace
}  // namespace collidescope
