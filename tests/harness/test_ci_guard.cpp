// The suite's guard for a missing package or right (support/ci.hpp): CI=true, and only that,
// turns the skip into a failure.

#include "support/ci.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace collidescope {
namespace {

// Sets CI for one scope and puts back what was there.
class ScopedCi {
public:
    explicit ScopedCi(const char* value) {
        if (const char* old = std::getenv("CI")) m_old = old;
        if (value != nullptr) {
            setenv("CI", value, 1);
        } else {
            unsetenv("CI");
        }
    }
    ~ScopedCi() {
        if (m_old) {
            setenv("CI", m_old->c_str(), 1);
        } else {
            unsetenv("CI");
        }
    }
    ScopedCi(const ScopedCi&) = delete;
    ScopedCi& operator=(const ScopedCi&) = delete;

private:
    std::optional<std::string> m_old;
};

void guard_of_a_missing_package() { COLLIDESCOPE_SKIP_OR_FAIL_UNDER_CI("libfoo is not installed"); }

TEST(CiGuard, OnlyCiEqualTrueIsCi) {
    {
        const ScopedCi ci("true");
        EXPECT_TRUE(testing::under_ci());
    }
    for (const char* other : {"", "1", "false", "TRUE", "yes"}) {
        const ScopedCi ci(other);
        EXPECT_FALSE(testing::under_ci()) << "CI=" << other;
    }
    const ScopedCi unset(nullptr);
    EXPECT_FALSE(testing::under_ci());
}

// Under CI the guard fails the test (a fatal failure, so nothing after it runs) and says why.
// Outside CI it skips, which this test cannot show without skipping itself.
TEST(CiGuard, UnderCiAMissingPackageFailsTheTest) {
    const ScopedCi ci("true");
    EXPECT_FATAL_FAILURE(guard_of_a_missing_package(), "CI=true, so not a skip: libfoo is not installed");
}

}  // namespace
}  // namespace collidescope
