#pragma once
// `collidescope check --regions FILE`: the frame's interpenetration regions (intersection
// curves, regions, their ids over frames: engine/include/collidescope/regions.hpp) as JSON
// Lines, one object per region per frame, and a line per region over the run at the end.

#include "collidescope/regions.hpp"
#include "collidescope/trace.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace collidescope::app {

class RegionsWriter final : public TraceSink {
public:
    /// `names`: the objects' names, by object index.
    RegionsWriter(std::ostream& out, std::vector<std::string> names) : m_out(out), m_names(std::move(names)) {}
    void on_frame(const FrameReport& report) override;

    /// "region 3: objects 'hand' and 'hip', frames 41-63 (23 frames), curve 0.14 at most (frame
    /// 52), 120 pairs at most; split from region 1": one per region track, in id order.
    std::vector<std::string> summary_lines() const;
    std::size_t region_count() const { return m_tracker.tracks().size(); }
    /// Milliseconds spent finding and following regions (not writing them).
    double ms() const { return m_ms; }

private:
    std::ostream& m_out;
    std::vector<std::string> m_names;
    RegionTracker m_tracker;
    double m_ms = 0;
};

/// One region of one frame as the JSON object `--regions` writes (without a newline).
std::string region_json(std::uint32_t frame, const Region& region, const std::vector<std::string>& names);

}  // namespace collidescope::app
