#pragma once
// Debian's assimp-testmodels in the mesh and scene tests: where a model lies, and what to do
// when the package is missing (a skip on a developer's machine, a failure under CI=true).

#include "support/ci.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace collidescope::testmodels {

inline const std::filesystem::path k_root = "/usr/share/assimp/models";

/// The model's path, or an empty path when it is not installed (REQUIRE_TESTMODEL then skips
/// the test, or fails it under CI).
inline std::filesystem::path find(const std::string& relative) {
    const std::filesystem::path file = k_root / relative;
    if (std::filesystem::is_regular_file(file)) return file;
    return {};
}

}  // namespace collidescope::testmodels

/// Binds `var` to the model's path; a missing model skips the test, or fails it under CI=true.
#define REQUIRE_TESTMODEL(var, relative)                                                              \
    const std::filesystem::path var = ::collidescope::testmodels::find(relative);                     \
    if (var.empty()) {                                                                                \
        COLLIDESCOPE_SKIP_OR_FAIL_UNDER_CI("assimp-testmodels not installed (" << (relative) << ")"); \
    }
