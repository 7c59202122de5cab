// The brute method's result does not depend on the thread count (Box2D's determinism test):
// pairs, their hash and every count are equal for 1 to 4 threads.

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/pipeline.hpp"

#include <gtest/gtest.h>

namespace collidescope {
namespace {

std::uint64_t hash_pairs(const std::vector<TrianglePair>& pairs) {
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a
    for (const TrianglePair& pair : pairs) {
        for (const std::uint32_t value : {pair.obj_a, pair.tri_a, pair.obj_b, pair.tri_b}) {
            hash = (hash ^ value) * 1099511628211ull;
        }
    }
    return hash;
}

struct SceneRun {
    std::vector<std::uint64_t> hashes;  ///< per frame
    std::vector<FrameCounts> counts;    ///< per frame
};

SceneRun run_scene(const Scene& scene, int threads) {
    Pipeline pipeline({"brute", true, threads});
    SceneRun run;
    for (const Frame& frame : testing::all_frames(scene)) {
        const FrameResult result = pipeline.process(frame);
        EXPECT_EQ(result.colliding_pairs, testing::reference_colliding_pairs(frame, true))
            << "threads " << threads << ", frame " << frame.index;
        run.hashes.push_back(hash_pairs(result.colliding_pairs));
        run.counts.push_back(result.stats.counts);
    }
    return run;
}

void expect_equal_counts(const FrameCounts& a, const FrameCounts& b) {
    for_each_count(a, [&](const char* name, std::uint64_t value) {
        std::uint64_t other = 0;
        for_each_count(b, [&](const char* other_name, std::uint64_t v) {
            if (std::string_view(name) == other_name) other = v;
        });
        EXPECT_EQ(value, other) << name;
    });
}

TEST(BruteDeterminism, SameResultForEveryThreadCount) {
    const std::uint64_t seed = 11;
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene scene = testing::random_scene(seed, {6, 3, 300, 12});
    const SceneRun one_thread = run_scene(scene, 1);
    std::uint64_t total_pairs = 0;
    for (const FrameCounts& counts : one_thread.counts) total_pairs += counts.colliding_pairs;
    ASSERT_GT(total_pairs, 0u);
    for (int threads = 2; threads <= 4; ++threads) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        const SceneRun run = run_scene(scene, threads);
        EXPECT_EQ(run.hashes, one_thread.hashes);
        ASSERT_EQ(run.counts.size(), one_thread.counts.size());
        for (std::size_t f = 0; f < run.counts.size(); ++f) expect_equal_counts(run.counts[f], one_thread.counts[f]);
    }
}

}  // namespace
}  // namespace collidescope
