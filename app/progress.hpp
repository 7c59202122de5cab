#pragma once
// Log lines and a progress bar on stderr. The bar appears only when stderr is a terminal and
// the run is long (still going after a second); log lines go above it.

#include <chrono>
#include <cstdint>
#include <string>

namespace collidescope::app {

/// Writes log lines to stderr and, when worthwhile, a progress bar below them.
class Progress {
public:
    /// `total` steps (frames); the bar is enabled only when stderr is a terminal.
    explicit Progress(std::uint64_t total);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Prints one line (no newline in `line`) on stderr, above the bar.
    void log(const std::string& line);
    /// One more step done; redraws the bar at most ten times a second.
    void advance();
    /// Removes the bar (before the final summary or an error message).
    void finish();

private:
    void draw();
    void erase();

    using Clock = std::chrono::steady_clock;
    std::uint64_t m_total;
    std::uint64_t m_done = 0;
    bool m_enabled;                  ///< stderr is a terminal
    bool m_visible = false;          ///< the bar is on screen now
    Clock::time_point m_start = Clock::now();
    Clock::time_point m_last_draw{};
};

}  // namespace collidescope::app
