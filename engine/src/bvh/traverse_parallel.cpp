// The parallel traversal: a breadth-first expansion of the root items to a fixed number of
// items, then one depth-first traversal per item in parallel with thread-local buffers.
// Every item is processed exactly once whatever the schedule, so the counts and the set of
// candidates are the same for every thread count.

#include "bvh/traverse.hpp"

#include "stats/stopwatch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <optional>

namespace collidescope::bvh {
namespace {

void step(const WorkItem& item, std::span<const MeshView> meshes, std::vector<WorkItem>& stack,
          CandidateBuffer& candidates, TraversalStats& stats) {
    if (item.wide) {
        step_wide(item, meshes, stack, candidates, stats);
    } else if (item.obj_a == item.obj_b && item.node_a == item.node_b) {
        step_self(item, meshes, stack, candidates, stats);
    } else {
        step_pair(item, meshes, stack, candidates, stats);
    }
}

struct Local {
    CandidateBuffer candidates;
    std::vector<WorkItem> stack;
    TraversalStats stats;

    void clear() {
        candidates.clear();
        stack.clear();
        stats = {};
    }
};

// Breadth-first rounds until there are enough items to share out (or none are left).
std::vector<WorkItem> expand(std::vector<WorkItem> items, std::span<const MeshView> meshes,
                             std::uint32_t target, Local& serial) {
    for (int round = 0; round < 64 && !items.empty() && items.size() < target; ++round) {
        std::vector<WorkItem> next;
        for (const WorkItem& item : items) step(item, meshes, next, serial.candidates, serial.stats);
        items = std::move(next);
    }
    return items;
}

}  // namespace

class TraversalBuffers {
public:
    Local serial;
    tbb::enumerable_thread_specific<Local> locals;
};

std::shared_ptr<TraversalBuffers> make_traversal_buffers() { return std::make_shared<TraversalBuffers>(); }

TraversalStats traverse(std::vector<WorkItem> roots, std::span<const MeshView> meshes,
                        const TraversalConfig& config, std::vector<TrianglePair>& candidates,
                        TraversalBuffers* reused) {
    const Stopwatch stopwatch;
    std::optional<TraversalBuffers> own;  // only for a caller that keeps none
    TraversalBuffers& buffers = reused ? *reused : own.emplace();
    Local& serial = buffers.serial;
    serial.clear();
    for (Local& local : buffers.locals) local.clear();
    const std::vector<WorkItem> items = expand(std::move(roots), meshes, config.parallel_items, serial);
    tbb::enumerable_thread_specific<Local>& locals = buffers.locals;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        Local& local = locals.local();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            local.stack.push_back(items[i]);
            while (!local.stack.empty()) {
                const WorkItem item = local.stack.back();
                local.stack.pop_back();
                step(item, meshes, local.stack, local.candidates, local.stats);
            }
        }
    });
    TraversalStats stats = serial.stats;
    std::size_t total = candidates.size() + serial.candidates.size();
    for (const Local& local : locals) total += local.candidates.size();
    candidates.reserve(total);
    candidates.insert(candidates.end(), serial.candidates.begin(), serial.candidates.end());
    for (const Local& local : locals) {
        stats.add(local.stats);
        candidates.insert(candidates.end(), local.candidates.begin(), local.candidates.end());
    }
    stats.ms = stopwatch.elapsed_ms();
    return stats;
}

}  // namespace collidescope::bvh
