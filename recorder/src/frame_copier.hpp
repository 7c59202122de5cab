#pragma once
// What the writer thread needs of a frame, copied off the engine's spans on the engine's
// thread: positions to float32, pairs, stats and the methods' details (frame_queue.hpp).

#include "frame_queue.hpp"

#include "collidescope/trace.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace collidescope::recorder {

class FrameCopier {
public:
    /// `file` names the recording in errors (an unknown method).
    explicit FrameCopier(std::string file);

    /// The frame as a record; a topology is attached on the first frame and whenever an
    /// object's Topology::revision changed since the last frame copied.
    FrameRecord copy(const FrameReport& report);
    /// The method names, in the order of the recording's method enum.
    const std::vector<std::string>& methods() const { return m_methods; }

private:
    std::string m_file;
    std::vector<std::string> m_methods;
    std::vector<std::uint64_t> m_revisions;  ///< last topology revision copied, per object
    bool m_first = true;
};

}  // namespace collidescope::recorder
