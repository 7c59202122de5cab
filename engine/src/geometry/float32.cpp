// Rounding doubles to float32: the one place the code base writes the round trip
// double -> float -> double (to the nearest float32, and to the float32 on one side).
//
// GCC 12.2's SLP vectorizer (-O2 and -O3) miscompiles that round trip when two of them fill
// neighbouring doubles: it packs the unconverted inputs into one vector and drops both
// conversions, so the values stay unrounded (docs/how-to/toolchain.md has the twelve-line
// reproducer; clang, -O1 and -fno-tree-slp-vectorize round correctly). An exact engine cannot
// have values change behind its back, so this file is compiled with -fno-tree-slp-vectorize on
// GCC < 13 (engine/CMakeLists.txt), and the functions stay out of line: a caller sees a call,
// never a conversion its own vectorizer could drop. tests/geometry/test_float32.cpp checks
// the rounding against values written in hexadecimal.

#include "geometry/float32.hpp"

#include "collidescope/types.hpp"

#include <cmath>
#include <limits>

namespace collidescope {

double round_to_float32(double x) { return static_cast<double>(static_cast<float>(x)); }

Vec3 round_to_float32(const Vec3& point) {
    return {round_to_float32(point.x()), round_to_float32(point.y()), round_to_float32(point.z())};
}

bool is_float32(double x) { return round_to_float32(x) == x; }

// The nearest float, stepped once away from x where it lies on the wrong side (std::nextafter
// from infinity gives the largest finite float; from zero, the smallest subnormal).
float float32_below(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float float32_above(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace collidescope
