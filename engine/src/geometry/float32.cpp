// Rounding doubles to float32: the one place the code base writes the round trip
// double -> float -> double.
//
// GCC 12.2's SLP vectorizer (-O2 and -O3) miscompiles that round trip when two of them fill
// neighbouring doubles: it packs the unconverted inputs into one vector and drops both
// conversions, so the values stay unrounded (docs/how-to/toolchain.md has the twelve-line
// reproducer; clang, -O1 and -fno-tree-slp-vectorize round correctly). An exact engine cannot
// have values change behind its back, so this file is compiled with -fno-tree-slp-vectorize on
// GCC < 13 (engine/CMakeLists.txt), and the functions stay out of line: a caller sees a call,
// never a conversion its own vectorizer could drop. tests/geometry/test_float32.cpp checks
// the rounding against values written in hexadecimal.

#include "collidescope/types.hpp"

namespace collidescope {

double round_to_float32(double x) { return static_cast<double>(static_cast<float>(x)); }

Vec3 round_to_float32(const Vec3& point) {
    return {round_to_float32(point.x()), round_to_float32(point.y()), round_to_float32(point.z())};
}

bool is_float32(double x) { return round_to_float32(x) == x; }

}  // namespace collidescope
