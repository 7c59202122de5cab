// Splitting a frame range into one contiguous block per rank (ranks/ranks.hpp).

#include "ranks/ranks.hpp"

#include "collidescope/error.hpp"

namespace collidescope::app::ranks {

FrameRange block_of(FrameRange range, int rank, int size) {
    const std::uint32_t frames = range.end - range.begin;
    if (size < 1 || rank < 0 || rank >= size) throw InputError("bad rank " + std::to_string(rank) + " of " + std::to_string(size));
    const auto ranks = static_cast<std::uint32_t>(size);
    const auto r = static_cast<std::uint32_t>(rank);
    if (ranks > frames) {
        throw InputError(std::to_string(size) + " ranks for " + std::to_string(frames) +
                         " frames: run at most one rank per frame");
    }
    const std::uint32_t base = frames / ranks;
    const std::uint32_t extra = frames % ranks;  // the first `extra` ranks take one frame more
    const std::uint32_t begin = range.begin + r * base + std::min(r, extra);
    return {begin, begin + base + (r < extra ? 1u : 0u)};
}

}  // namespace collidescope::app::ranks
