// Finding a sanitizer report in a child's stderr.

#include "support/sanitizer_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace collidescope::testing {
namespace {

// What each runtime prints on the line that opens or closes a report (gcc 12's libsanitizer):
// "==PID==ERROR: AddressSanitizer: heap-buffer-overflow ...", "==PID==ERROR: LeakSanitizer:
// detected memory leaks", "FILE:LINE:COL: runtime error: ..." (UBSan), "WARNING:
// ThreadSanitizer: data race ...", and the SUMMARY line each of them ends with.
constexpr std::array<std::string_view, 6> k_markers = {
    "ERROR: AddressSanitizer", "ERROR: LeakSanitizer",     "runtime error: ",
    "WARNING: ThreadSanitizer", "ERROR: ThreadSanitizer", "SUMMARY: UndefinedBehaviorSanitizer",
};

}  // namespace

std::string sanitizer_report_line(std::string_view text) {
    std::size_t first = std::string_view::npos;
    for (const std::string_view marker : k_markers) first = std::min(first, text.find(marker));
    if (first == std::string_view::npos) return "";
    const std::size_t begin = text.rfind('\n', first);
    const std::size_t start = begin == std::string_view::npos ? 0 : begin + 1;
    const std::size_t end = text.find('\n', first);
    return std::string(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
}

void expect_no_sanitizer_report(const std::string& err, int exit_code, const std::string& what) {
    const std::string line = sanitizer_report_line(err);
    if (!line.empty()) {
        ADD_FAILURE() << what << ": a sanitizer report (exit code " << exit_code << "): " << line << "\n" << err;
    } else if (exit_code == k_sanitizer_exit_code) {
        ADD_FAILURE() << what << ": exited " << k_sanitizer_exit_code
                      << ", the sanitizers' exit code, without a report on stderr:\n" << err;
    }
}

}  // namespace collidescope::testing
