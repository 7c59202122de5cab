#pragma once
// How many cases a random or exhaustive sweep runs. The normal build runs every sweep in full;
// a sanitizer build runs the first part of the same sequence (the same seeds, the same first
// cases), because what the sanitizers look for, a bad access or undefined behaviour on some
// path, a fraction of the cases already walks, and the address suite has CI's 2 cores for a
// quarter of its 45 minutes (docs/how-to/sanitizers.md). The seeds and case numbers stay in
// each test's output or failure messages, so a failing case is reproduced in either build.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace collidescope::testing {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

// `full` in the normal build; `full / divisor` (at least 1) in a sanitizer build.
constexpr int sweep_size(int full, int divisor = 4) {
    return kSanitizerBuild ? std::max(1, full / divisor) : full;
}

// The first sweep_size(all.size(), divisor) of a list of seeds or cases given in full.
template <typename T>
std::vector<T> sweep_of(std::vector<T> all, int divisor = 4) {
    all.resize(static_cast<std::size_t>(sweep_size(static_cast<int>(all.size()), divisor)));
    return all;
}

}  // namespace collidescope::testing
