// The brute-force culling: all triangle pairs, a closed box prefilter.

#include "brute/brute_cull.hpp"

#include "brute/triangle_boxes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <functional>

namespace collidescope::brute {
namespace {

using PairBuffers = tbb::enumerable_thread_specific<std::vector<TrianglePair>>;

// Candidates of objects a < b: every (i, j) whose boxes overlap. Parallel over i.
void prefilter_pair(std::uint32_t a, const std::vector<TriangleBox>& boxes_a, std::uint32_t b,
                    const std::vector<TriangleBox>& boxes_b, PairBuffers& candidates,
                    tbb::combinable<std::uint64_t>& box_tests) {
    const auto count_b = static_cast<std::uint32_t>(boxes_b.size());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, static_cast<std::uint32_t>(boxes_a.size())),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
        std::vector<TrianglePair>& out = candidates.local();
        for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
            for (std::uint32_t j = 0; j < count_b; ++j) {
                if (boxes_overlap(boxes_a[i], boxes_b[j])) out.push_back({a, i, b, j});
            }
        }
        box_tests.local() += std::uint64_t{range.size()} * count_b;
    });
}

// Candidates within object a: every (i, j), i < j, whose boxes overlap. Parallel over i.
void prefilter_self(std::uint32_t a, const std::vector<TriangleBox>& boxes, PairBuffers& candidates,
                    tbb::combinable<std::uint64_t>& box_tests) {
    const auto count = static_cast<std::uint32_t>(boxes.size());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
        std::vector<TrianglePair>& out = candidates.local();
        std::uint64_t tests = 0;
        for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
            for (std::uint32_t j = i + 1; j < count; ++j) {
                if (boxes_overlap(boxes[i], boxes[j])) out.push_back({a, i, a, j});
            }
            tests += count - 1 - i;
        }
        box_tests.local() += tests;
    });
}

// Triangle boxes of the objects that appear in some object pair (others stay empty).
std::vector<std::vector<TriangleBox>> boxes_of_paired_objects(const FrameContext& context) {
    std::vector<std::vector<TriangleBox>> boxes(context.frame.objects.size());
    std::vector<bool> needed(context.frame.objects.size(), false);
    for (const ObjectPair& pair : context.object_pairs) needed[pair.a] = needed[pair.b] = true;
    for (std::size_t o = 0; o < boxes.size(); ++o) {
        if (needed[o]) boxes[o] = triangle_boxes(context.frame.objects[o]);
    }
    return boxes;
}

}  // namespace

std::vector<TrianglePair> brute_cull(const FrameContext& context, FrameStats& stats) {
    const std::vector<std::vector<TriangleBox>> boxes = boxes_of_paired_objects(context);
    PairBuffers buffers;
    tbb::combinable<std::uint64_t> box_tests([] { return std::uint64_t{0}; });
    for (const ObjectPair& pair : context.object_pairs) {
        if (pair.a != pair.b) {
            prefilter_pair(pair.a, boxes[pair.a], pair.b, boxes[pair.b], buffers, box_tests);
        } else if (context.self_collision) {
            prefilter_self(pair.a, boxes[pair.a], buffers, box_tests);
        }
    }
    std::vector<TrianglePair> candidates;
    for (const std::vector<TrianglePair>& buffer : buffers) {
        candidates.insert(candidates.end(), buffer.begin(), buffer.end());
    }
    stats.counts.box_tests += box_tests.combine(std::plus<>());
    stats.counts.candidate_pairs += candidates.size();
    return candidates;
}

}  // namespace collidescope::brute
