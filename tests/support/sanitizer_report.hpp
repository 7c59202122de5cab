#pragma once
// A child process's sanitizer report, found in its stderr whatever its exit code: the tests
// that run the built command line accept exit codes such as 1 ("collisions found") or 2 (a
// refused input), which a sanitizer's own exit could otherwise pass for.

#include <string>
#include <string_view>

namespace collidescope::testing {

/// The exit code of every sanitizer in the sanitizer builds (tests/sanitize/*_defaults.cpp,
/// scripts/sanitize.sh): no command exits with it, so a report never passes for an answer.
inline constexpr int k_sanitizer_exit_code = 86;

/// The first line of a sanitizer report in `text` (AddressSanitizer, LeakSanitizer,
/// UndefinedBehaviorSanitizer, ThreadSanitizer), or "" when there is none.
std::string sanitizer_report_line(std::string_view text);

/// Adds a test failure when `err` (a child's stderr) holds a sanitizer report or the child
/// exited with k_sanitizer_exit_code. `what` names the child in the message.
void expect_no_sanitizer_report(const std::string& err, int exit_code, const std::string& what);

}  // namespace collidescope::testing
