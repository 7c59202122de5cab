#pragma once
// Frames rendered in parallel, out of order, into a clip in order (replays/src, private).

#include "video_encoder.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace collidescope::replays {

/// Holds frames that arrive before their turn and feeds the encoder each frame in ordinal
/// order, from whichever thread hands in the next one. Render threads take frames from a
/// shared counter in order, so at most about one frame per thread waits here. Thread-safe.
class OrderedVideo {
public:
    explicit OrderedVideo(std::unique_ptr<VideoEncoder> encoder) : m_encoder(std::move(encoder)) {}

    /// Frame `ordinal` (0 = the first of the clip), width * height RGBA. Encodes it and every
    /// waiting frame after it when it is the next one. Throws what the encoder throws.
    void add(std::uint64_t ordinal, std::vector<std::uint8_t> rgba);
    /// Completes the clip (every ordinal before `frames` must have been added). Throws
    /// InputError naming the file when a frame is missing or writing fails.
    void finish(std::uint64_t frames);
    /// Seconds spent encoding so far.
    double seconds() const;

private:
    mutable std::mutex m_lock;
    std::unique_ptr<VideoEncoder> m_encoder;
    std::map<std::uint64_t, std::vector<std::uint8_t>> m_waiting;
    std::uint64_t m_next = 0;
    double m_seconds = 0;
};

}  // namespace collidescope::replays
