#pragma once
// Doubles rounded to the float32 on one side (engine/src/geometry, private): the exact bounds
// that a float box needs to hold a double one. Written in float32.cpp with the round trip
// (round_to_float32's file: docs/how-to/toolchain.md says why it is the only one).

namespace collidescope {

/// The largest float not above `x` (x itself when it is a float32; -infinity for -infinity;
/// the largest finite float for x past it; NaN for NaN).
float float32_below(double x);

/// The smallest float not below `x` (float32_below's mirror).
float float32_above(double x);

}  // namespace collidescope
