// OrderedVideo: out-of-order frames into the encoder in order.

#include "ordered_video.hpp"

#include "collidescope/error.hpp"

#include <chrono>

namespace collidescope::replays {

void OrderedVideo::add(std::uint64_t ordinal, std::vector<std::uint8_t> rgba) {
    const std::lock_guard<std::mutex> guard(m_lock);
    m_waiting.emplace(ordinal, std::move(rgba));
    const auto start = std::chrono::steady_clock::now();
    for (auto next = m_waiting.find(m_next); next != m_waiting.end(); next = m_waiting.find(m_next)) {
        m_encoder->add_frame(next->second);
        m_waiting.erase(next);
        ++m_next;
    }
    m_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void OrderedVideo::finish(std::uint64_t frames) {
    const std::lock_guard<std::mutex> guard(m_lock);
    if (m_next != frames || !m_waiting.empty()) {
        throw InputError("video: frame " + std::to_string(m_next) + " of " + std::to_string(frames) +
                         " never came (a render thread failed)");
    }
    const auto start = std::chrono::steady_clock::now();
    m_encoder->finish();
    m_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double OrderedVideo::seconds() const {
    const std::lock_guard<std::mutex> guard(m_lock);
    return m_seconds;
}

}  // namespace collidescope::replays
