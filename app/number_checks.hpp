#pragma once
// Checks of numeric options that say what the option wants in words: `--fps 0` is "--fps: must
// be a positive number of frames per second, not '0'", where CLI11's own PositiveNumber printed
// a range up to DBL_MAX in 300 digits. Non-numbers, NaN and infinities are refused alike.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace collidescope::app {

/// A finite number > 0; `what` ends "must be a positive number `what`" (e.g. "of frames per second").
CLI::Validator positive_number(const std::string& what);

/// A finite number >= 0; "must be a number, 0 or more, `what`".
CLI::Validator non_negative_number(const std::string& what);

/// A whole number in [low, high]; "must be a whole number from low to high `what`".
CLI::Validator whole_number(std::int64_t low, std::int64_t high, const std::string& what);

/// The text of the check, for its tests: "" when `value` passes, else the message.
std::string number_check_message(const CLI::Validator& check, std::string value);

}  // namespace collidescope::app
