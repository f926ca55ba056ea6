// The exact last stage shared by the adaptive and interval predicates: the formula of
// arithmetic/formulas.hpp evaluated in GMP integers after scaling every input by one
// power of two. [MK89 §3.3] (the paper's multiprecision fallback)
// Preconditions: finite inputs. Exact for every finite double: subnormals, values near
// DBL_MAX, and any mix of magnitudes (the integers grow to about 2100 bits at most).
#pragma once

#include <gmpxx.h>

#include <array>
#include <algorithm>
#include <climits>
#include <cstddef>
#include <cmath>

#include "arithmetic/formulas.hpp"

namespace mk::gmp {

// The n doubles of v as integers z[i] = v[i] * 2^-e_min, one power of two for all: every
// finite double is m * 2^e with an integer |m| < 2^53, and e_min is the least such e among
// the non-zero ones. A predicate whose sign does not change under a positive common factor
// (a homogeneous form) can then be evaluated in integers, which avoid the gcd work that
// rationals do after every operation.
inline void scaled_integers(const double* v, std::size_t n, mpz_class* z) {
  int e_min = INT_MAX;
  for (std::size_t i = 0; i < n; ++i) {
    if (v[i] == 0.0) continue;
    int e = 0;
    (void)std::frexp(v[i], &e);  // v = f * 2^e, 0.5 <= |f| < 1, so v = (f * 2^53) * 2^(e - 53)
    e_min = std::min(e_min, e - 53);
  }
  for (std::size_t i = 0; i < n; ++i) {
    mpz_ptr zi = z[i].get_mpz_t();
    if (v[i] == 0.0) {
      mpz_set_ui(zi, 0);
      continue;
    }
    int e = 0;
    const double f = std::frexp(v[i], &e);
    mpz_set_d(zi, std::ldexp(f, 53));  // an integer below 2^53: exact
    mpz_mul_2exp(zi, zi, static_cast<mp_bitcnt_t>(e - 53 - e_min));
  }
}

// Sign of (q1 - p1) x (q2 - p2), a degree-2 form, in scaled integers.
inline int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                      double q2x, double q2y) {
  const std::array<double, 8> v{p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y};
  std::array<mpz_class, 8> z;
  scaled_integers(v.data(), v.size(), z.data());
  return sgn(formula::cross_of_differences<mpz_class>(z[0], z[1], z[2], z[3], z[4], z[5], z[6], z[7]));
}

inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return cross_sign(ax, ay, bx, by, ax, ay, cx, cy);  // (b - a) x (c - a)
}

inline int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                          double q2x, double q2y) {
  return cross_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
}

}  // namespace mk::gmp
