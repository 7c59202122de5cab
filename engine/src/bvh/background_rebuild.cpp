// The background rebuild: std::async on its own thread; the future is the only shared state
// (its get() orders the worker's writes before the engine's reads).

#include "bvh/background_rebuild.hpp"

#include <cassert>
#include <chrono>

namespace collidescope::bvh {

BackgroundRebuild::~BackgroundRebuild() {
    if (m_result.valid()) m_result.wait();
}

void BackgroundRebuild::start(std::vector<RebuildJob> jobs) {
    assert(!busy());
    m_result = std::async(std::launch::async, [jobs = std::move(jobs)]() mutable {
        std::vector<RebuiltTree> trees;
        trees.reserve(jobs.size());
        for (RebuildJob& job : jobs) {
            RebuiltTree rebuilt;
            rebuilt.stats = build_tree(job.topology->triangles, job.vertices, job.config, rebuilt.tree);
            rebuilt.job = std::move(job);
            trees.push_back(std::move(rebuilt));
        }
        return trees;
    });
}

bool BackgroundRebuild::ready() const {
    return m_result.valid() && m_result.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

std::optional<std::vector<RebuiltTree>> BackgroundRebuild::take(bool wait) {
    if (!m_result.valid()) return std::nullopt;
    if (!wait && m_result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    return m_result.get();
}

}  // namespace collidescope::bvh
