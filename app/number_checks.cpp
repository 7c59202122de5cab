// Numeric option checks with messages in words (number_checks.hpp).

#include "number_checks.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace collidescope::app {
namespace {

std::optional<double> finite_number(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) != 0) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<std::int64_t> whole(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) != 0) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size() || errno == ERANGE) return std::nullopt;
    return value;
}

std::string refused(const std::string& wanted, const std::string& value) {
    return "must be " + wanted + ", not '" + value + "'";
}

}  // namespace

CLI::Validator positive_number(const std::string& what) {
    const std::string wanted = "a positive number " + what;
    return CLI::Validator(
        [wanted](std::string& value) {
            const std::optional<double> number = finite_number(value);
            return number && *number > 0 ? std::string() : refused(wanted, value);
        },
        "POSITIVE");
}

CLI::Validator non_negative_number(const std::string& what) {
    const std::string wanted = "a number, 0 or more, " + what;
    return CLI::Validator(
        [wanted](std::string& value) {
            const std::optional<double> number = finite_number(value);
            return number && *number >= 0 ? std::string() : refused(wanted, value);
        },
        "NONNEGATIVE");
}

CLI::Validator whole_number(std::int64_t low, std::int64_t high, const std::string& what) {
    const std::string wanted = "a whole number from " + std::to_string(low) + " to " + std::to_string(high) + " " + what;
    return CLI::Validator(
        [wanted, low, high](std::string& value) {
            const std::optional<std::int64_t> number = whole(value);
            return number && *number >= low && *number <= high ? std::string() : refused(wanted, value);
        },
        "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}

std::string number_check_message(const CLI::Validator& check, std::string value) { return check(value); }

}  // namespace collidescope::app
