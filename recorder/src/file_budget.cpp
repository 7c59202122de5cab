// --budget's decimation (file_budget.hpp).

#include "file_budget.hpp"

#include <algorithm>

namespace collidescope::recorder {
namespace {

double grown(std::uint64_t now, std::uint64_t base) { return static_cast<double>(now - std::min(now, base)); }

// Bytes per kept frame of one kind, from the growth since the base (or the whole, early on).
double per_kept(std::uint64_t bytes, std::uint64_t kept, std::uint64_t base_bytes, std::uint64_t base_kept) {
    const double since = grown(kept, base_kept);
    if (since > 0) return grown(bytes, base_bytes) / since;
    return kept > 0 ? static_cast<double>(bytes) / static_cast<double>(kept) : 0.0;
}

}  // namespace

bool FileBudget::keep_depth() {
    const std::uint64_t index = m_depth_frames++;
    return m_depth.stride != 0 && index % m_depth.stride == 0;
}

template <class Need>
void FileBudget::Stride::raise(double frames, double room, Need need) {
    while (stride != 0 && need(stride) > room) {
        if (frames / stride <= 1 || stride >= (1u << 30)) {
            stride = 0;
        } else {
            stride *= 2;
        }
    }
}

void FileBudget::update(const Usage& usage) {
    if (m_budget == 0 || usage.rows >= m_total) return;
    if (usage.rows <= k_warmup) {
        m_base = usage;
        if (usage.file_bytes < m_budget) return;  // decide on the first frames only when already over
    }
    const double remaining = static_cast<double>(m_total - usage.rows);
    const double rows = std::max(grown(usage.rows, m_base.rows), 1.0);
    const double kinds = grown(usage.positions_bytes, m_base.positions_bytes) + grown(usage.depth_bytes, m_base.depth_bytes);
    const double other = std::max(grown(usage.file_bytes, m_base.file_bytes) - kinds, 0.0) / rows;
    const double per_positions = per_kept(usage.positions_bytes, usage.positions_kept, m_base.positions_bytes, m_base.positions_kept);
    const double per_depth = per_kept(usage.depth_bytes, usage.depth_kept, m_base.depth_bytes, m_base.depth_kept);
    const double depth_frames = remaining * static_cast<double>(usage.depth_seen) / static_cast<double>(std::max<std::uint64_t>(usage.rows, 1));
    const double room = static_cast<double>(m_budget) - static_cast<double>(usage.file_bytes) - remaining * other;
    const auto positions_need = [&](std::uint32_t stride) { return stride == 0 ? 0.0 : remaining / stride * per_positions; };
    const auto depth_need = [&](std::uint32_t stride) { return stride == 0 ? 0.0 : depth_frames / stride * per_depth; };
    m_depth.raise(depth_frames, room, [&](std::uint32_t stride) { return depth_need(stride) + positions_need(m_positions.stride); });
    if (m_depth.stride == 0) m_positions.raise(remaining, room, positions_need);
}

}  // namespace collidescope::recorder
