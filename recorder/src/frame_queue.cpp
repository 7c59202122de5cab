// The bounded frame queue.

#include "frame_queue.hpp"

#include <algorithm>

namespace collidescope::recorder {

std::size_t FrameRecord::bytes() const {
    std::size_t total = sizeof(FrameRecord) + ms.size() * sizeof(double) + counts.size() * sizeof(std::uint64_t) +
                        pairs.size() * sizeof(TrianglePair) + (gpu.size() + aabb.size()) * sizeof(double) +
                        gpu_passes.size() * sizeof(std::uint64_t) +
                        (decision.size() + hybrid.size()) * sizeof(double) +
                        survivors.size() * sizeof(survivors[0]) + regions.bytes() +
                        interval.bytes();
    for (const GpuDepthImage& image : depth_images) total += sizeof(GpuDepthImage) + image.depth.size() * sizeof(float);
    for (const ObjectRecord& object : objects) {
        total += sizeof(ObjectRecord) + object.positions.size() * sizeof(float);
        // A new topology is shared with the engine, but the writer keeps it alive: count it.
        if (object.new_topology) total += object.new_topology->triangles.size() * sizeof(TriIndices);
    }
    return total;
}

bool FrameQueue::push(FrameRecord record) {
    const std::size_t size = record.bytes();
    std::unique_lock lock(m_mutex);
    m_not_full.wait(lock, [&] { return m_closed || m_frames.empty() || m_bytes + size <= m_cap; });
    if (m_closed) return false;
    m_frames.emplace_back(std::move(record), size);
    m_bytes += size;
    if (m_bytes > m_peak) m_peak = m_bytes;
    m_not_empty.notify_one();
    return true;
}

FrameQueue::Taken FrameQueue::take_waiting(std::size_t max_frames) {
    std::unique_lock lock(m_mutex);
    m_not_empty.wait(lock, [&] { return m_closed || !m_frames.empty(); });
    Taken taken;
    while (!m_frames.empty() && taken.records.size() < std::max<std::size_t>(max_frames, 1)) {
        auto& [record, size] = m_frames.front();
        taken.records.push_back(std::move(record));
        taken.bytes += size;
        m_frames.pop_front();
    }
    return taken;
}

void FrameQueue::release(std::size_t bytes) {
    std::lock_guard lock(m_mutex);
    m_bytes -= std::min(bytes, m_bytes);
    m_not_full.notify_all();
}

void FrameQueue::close(bool discard) {
    std::lock_guard lock(m_mutex);
    m_closed = true;
    if (discard) {
        m_frames.clear();
        m_bytes = 0;
    }
    m_not_full.notify_all();
    m_not_empty.notify_all();
}

std::size_t FrameQueue::peak_bytes() const {
    std::lock_guard lock(m_mutex);
    return m_peak;
}

}  // namespace collidescope::recorder
