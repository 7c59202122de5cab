// Sizes on the command line and in messages.

#include "size_option.hpp"

#include "collidescope/error.hpp"

#include <charconv>
#include <cstdio>
#include <string_view>

namespace collidescope::app {

std::uint64_t parse_size(const std::string& text, const std::string& option) {
    std::uint64_t value = 0;
    const char* const end = text.data() + text.size();
    const std::from_chars_result parsed = std::from_chars(text.data(), end, value);
    const std::string_view suffix(parsed.ptr, static_cast<std::size_t>(end - parsed.ptr));
    std::uint64_t scale = 0;
    if (suffix.empty() || suffix == "B") scale = 1;
    if (suffix == "K" || suffix == "k" || suffix == "KB" || suffix == "kB" || suffix == "KiB") scale = 1ull << 10;
    if (suffix == "M" || suffix == "MB" || suffix == "MiB") scale = 1ull << 20;
    if (suffix == "G" || suffix == "GB" || suffix == "GiB") scale = 1ull << 30;
    if (parsed.ec != std::errc() || parsed.ptr == text.data() || scale == 0 || value == 0 || value > ~0ull / scale) {
        throw InputError(option + " must be a positive size such as 500K, 100M or 2G, not '" + text + "'");
    }
    return value * scale;
}

std::string format_size(std::uint64_t bytes) {
    if (bytes < 1024) return std::to_string(bytes) + " B";
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    double value = static_cast<double>(bytes) / 1024.0;
    int unit = 0;
    while (value >= 1024.0 && unit < 3) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
    return text;
}

}  // namespace collidescope::app
