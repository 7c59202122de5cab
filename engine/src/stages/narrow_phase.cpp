// The narrow phase over candidate pairs, in parallel.

#include "stages/narrow_phase.hpp"

#include "stats/stopwatch.hpp"

#include "collidescope/geometry.hpp"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace collidescope {

bool pair_collides(const Frame& frame, const TrianglePair& pair) {
    const ObjectFrame& a = frame.objects[pair.obj_a];
    const ObjectFrame& b = frame.objects[pair.obj_b];
    const std::array<Vec3, 3> pa = a.corners(pair.tri_a);
    const std::array<Vec3, 3> pb = b.corners(pair.tri_b);
    if (pair.obj_a == pair.obj_b) {
        return self_triangles_collide(a.topology->triangles[pair.tri_a], pa,
                                      b.topology->triangles[pair.tri_b], pb);
    }
    return triangles_intersect(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]);
}

void narrow_phase(const Frame& frame, std::span<const TrianglePair> candidates,
                  std::vector<TrianglePair>& colliding, FrameStats& stats) {
    const Stopwatch stopwatch;
    tbb::enumerable_thread_specific<std::vector<TrianglePair>> local_pairs;
    tbb::combinable<std::uint64_t> fallbacks([] { return std::uint64_t{0}; });
    tbb::combinable<std::uint64_t> shortcuts([] { return std::uint64_t{0}; });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        // A task body runs on one thread, so the thread-local counters' difference over the
        // body is exactly this body's fallbacks.
        const PredicateCounters before = predicate_counters();
        std::vector<TrianglePair>& out = local_pairs.local();
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            if (pair_collides(frame, candidates[k])) out.push_back(candidates[k]);
        }
        const PredicateCounters after = predicate_counters();
        fallbacks.local() += after.exact - before.exact;
        shortcuts.local() += after.shortcut - before.shortcut;
    });
    const std::size_t first = colliding.size();
    for (const std::vector<TrianglePair>& pairs : local_pairs) {
        colliding.insert(colliding.end(), pairs.begin(), pairs.end());
    }
    stats.counts.exact_tests += candidates.size();
    stats.counts.exact_fallbacks += fallbacks.combine(std::plus<>());
    stats.counts.exact_shortcuts += shortcuts.combine(std::plus<>());
    stats.counts.colliding_pairs += colliding.size() - first;
    stats.ms.narrow += stopwatch.elapsed_ms();
}

}  // namespace collidescope
