// Sizes on the command line and in messages.

#include "size_option.hpp"

#include "collidescope/error.hpp"

#include <charconv>
#include <cstdio>

namespace collidescope::app {

std::uint64_t parse_size(const std::string& text, const std::string& option) {
    std::uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [next, error] = std::from_chars(text.data(), end, value);
    std::string suffix(next, end);
    if (suffix == "B" || suffix.empty()) suffix = "";
    else if (suffix.size() >= 2 && suffix.substr(1) == "iB") suffix = suffix.substr(0, 1);
    else if (suffix.size() == 2 && suffix[1] == 'B') suffix = suffix.substr(0, 1);
    std::uint64_t scale = 1;
    if (suffix == "K" || suffix == "k") scale = 1ull << 10;
    else if (suffix == "M") scale = 1ull << 20;
    else if (suffix == "G") scale = 1ull << 30;
    else if (!suffix.empty()) scale = 0;
    if (error != std::errc() || next == text.data() || scale == 0 || value == 0 || value > (~0ull) / scale) {
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
