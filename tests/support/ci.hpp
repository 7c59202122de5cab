#pragma once
// What a test does when this machine lacks something it needs (a package, mpirun, a tmpfs):
// on a developer's machine it skips and says why; under CI it fails, because CI's setup
// installs everything and a skip there would pass a test that never ran. Every guard of the
// suite reads CI the same way: CI=true (as .ci/run exports it; the Python guards,
// tests/mesh/check_model_corpus.py and tests/replays/record_replay_animated.py, read it alike).

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

namespace collidescope::testing {

/// True when the environment says CI=true.
inline bool under_ci() {
    const char* ci = std::getenv("CI");
    return ci != nullptr && std::string_view(ci) == "true";
}

}  // namespace collidescope::testing

/// Skips the test with `reason` (a streamable expression), or fails it under CI=true.
#define COLLIDESCOPE_SKIP_OR_FAIL_UNDER_CI(reason)                                            \
    do {                                                                                      \
        if (::collidescope::testing::under_ci()) FAIL() << "CI=true, so not a skip: " << reason; \
        GTEST_SKIP() << reason;                                                               \
    } while (0)
