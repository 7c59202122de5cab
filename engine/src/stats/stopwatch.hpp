#pragma once
// Wall-clock stage timing for the stats (engine/src/stats, private).
//
// std::chrono::steady_clock: monotonic, so a clock adjustment never yields a negative stage.

#include <chrono>

namespace collidescope {

/// Milliseconds on the steady clock since its epoch: a reading to subtract from another.
inline double steady_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Measures milliseconds since construction or the last lap.
class Stopwatch {
public:
    /// Milliseconds since the start (or the last lap()).
    double elapsed_ms() const {
        return std::chrono::duration<double, std::milli>(Clock::now() - m_start).count();
    }
    /// Milliseconds since the start (or the last lap()), then starts again.
    double lap_ms() {
        const Clock::time_point now = Clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - m_start).count();
        m_start = now;
        return ms;
    }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point m_start = Clock::now();
};

}  // namespace collidescope
