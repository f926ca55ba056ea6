// Shared helpers of the arithmetic tests: seeded random doubles of chosen magnitudes and
// exact rational views of doubles and expansions. [Sh97]
// Preconditions: none.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <span>
#include <string>

namespace mk::test {

// A double with random sign, random 52-bit mantissa and binary exponent uniform in
// [e_min, e_max]; exponents below -1022 give subnormals (rounded by ldexp).
inline double random_double(std::mt19937_64& rng, int e_min, int e_max) {
  std::uniform_int_distribution<int> exponent(e_min, e_max);
  const std::uint64_t mantissa = rng() >> 12;  // 52 bits
  const double significand = 1.0 + std::ldexp(static_cast<double>(mantissa), -52);
  const double v = std::ldexp(significand, exponent(rng));
  return (rng() & 1) ? -v : v;
}

// A double with `bits` significant bits at most (so that small multiples stay exact).
inline double random_short_double(std::mt19937_64& rng, int bits, int e_min, int e_max) {
  std::uniform_int_distribution<int> exponent(e_min, e_max);
  const std::uint64_t mantissa = (rng() >> (64 - bits)) | (std::uint64_t{1} << (bits - 1));
  const double v = std::ldexp(static_cast<double>(mantissa), exponent(rng) - bits + 1);
  return (rng() & 1) ? -v : v;
}

inline mpq_class exact(double v) { return mpq_class(v); }

inline mpq_class exact(std::span<const double> e) {
  mpq_class sum = 0;
  for (const double c : e) sum += mpq_class(c);
  return sum;
}

// Exact hexadecimal form, for failure messages that reproduce bit for bit.
inline std::string hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

}  // namespace mk::test
