// The stderr progress bar.

#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace collidescope::app {
namespace {

constexpr auto k_show_after = std::chrono::seconds(1);
constexpr auto k_redraw_every = std::chrono::milliseconds(100);
constexpr int k_bar_width = 40;

}  // namespace

Progress::Progress(std::uint64_t total) : m_total(total), m_enabled(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::log(const std::string& line) {
    const bool was_visible = m_visible;
    erase();
    std::fprintf(stderr, "%s\n", line.c_str());
    if (was_visible) draw();
}

void Progress::advance() {
    ++m_done;
    if (!m_enabled || m_done >= m_total) return;
    const Clock::time_point now = Clock::now();
    if (now - m_start < k_show_after || now - m_last_draw < k_redraw_every) return;
    m_last_draw = now;
    erase();
    draw();
}

void Progress::finish() {
    erase();
    m_enabled = false;
}

void Progress::draw() {
    const auto filled = static_cast<int>(k_bar_width * m_done / (m_total == 0 ? 1 : m_total));
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(k_bar_width - filled), ' ');
    std::fprintf(stderr, "[%s] %llu/%llu frames", bar.c_str(), static_cast<unsigned long long>(m_done),
                 static_cast<unsigned long long>(m_total));
    std::fflush(stderr);
    m_visible = true;
}

void Progress::erase() {
    if (!m_visible) return;
    std::fputs("\r\033[K", stderr);  // carriage return, clear to end of line
    m_visible = false;
}

}  // namespace collidescope::app
