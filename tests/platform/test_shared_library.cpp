// SharedLibrary (collidescope/shared_library.hpp): a library opened by soname gives its
// functions, and a missing library or function is an UnavailableError naming it.

#include "collidescope/shared_library.hpp"

#include "collidescope/error.hpp"

#include <gtest/gtest.h>

#include <zlib.h>

#include <string>

namespace collidescope {
namespace {

std::string unavailable_text(void (*attempt)()) {
    try {
        attempt();
    } catch (const UnavailableError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(SharedLibrary, GivesTheFunctionsOfALibraryOpenedBySoname) {
    const SharedLibrary zlib("libz.so.1");
    EXPECT_EQ(zlib.soname(), "libz.so.1");
    const auto version = zlib.function<decltype(&::zlibVersion)>("zlibVersion");
    ASSERT_NE(version, nullptr);
    // The same library as the one linked into this test: the same version string.
    EXPECT_STREQ(version(), ::zlibVersion());
}

TEST(SharedLibrary, AMissingLibraryOrFunctionIsNamed) {
    const std::string library = unavailable_text([] { SharedLibrary("libcollidescope-no-such-library.so.7"); });
    EXPECT_NE(library.find("libcollidescope-no-such-library.so.7: "), std::string::npos) << library;
    const std::string function = unavailable_text([] { (void)SharedLibrary("libz.so.1").address("no_such_function"); });
    EXPECT_NE(function.find("libz.so.1: no function no_such_function"), std::string::npos) << function;
}

}  // namespace
}  // namespace collidescope
