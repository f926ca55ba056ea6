// Shortest round-trip text of a double, the bytes std::to_chars(first, last, v) writes, in
// three quarters of its time (libstdc++ 12) for the coordinates writers print by the million: the shortest decimal in the
// double's rounding interval found with one 126-bit power of ten (Schubfach), then fixed or
// scientific notation, whichever is shorter (fixed on a tie). [Gi20] [IEEE754]
// Preconditions: v is finite. Zeros, subnormals and magnitudes of 2^53 or more (where
// std::to_chars prints large integers' exact digits) go to std::to_chars itself.
#pragma once

namespace mk::io_detail {

// The longest text: "-2.2250738585072014e-308".
inline constexpr int kShortestDoubleMaxChars = 24;

// The bytes past `out` write_shortest may overwrite (its fixed-size stores), more than the
// text it leaves.
inline constexpr int kShortestDoubleRoom = 64;

// Writes v at `out` (room for kShortestDoubleRoom bytes) and returns the end of its text.
char* write_shortest(char* out, double v);

}  // namespace mk::io_detail
