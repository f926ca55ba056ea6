// Correct rounding of a rational to the nearest double, for output only.
// Preconditions: none (values beyond the double range round to +-infinity).
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "arithmetic/kernels/rational_kernel.hpp"

namespace mk {

inline double RationalKernel::to_nearest(const mpq_class& q) {
  // mpq_get_d truncates toward zero; the nearest double is it or its neighbour away from 0.
  const double t = q.get_d();
  if (mpq_class(t) == q) return t;
  const double away = std::nextafter(t, q > 0 ? std::numeric_limits<double>::infinity()
                                              : -std::numeric_limits<double>::infinity());
  if (!std::isfinite(away)) return away;
  const mpq_class dt = abs(q - mpq_class(t));
  const mpq_class da = abs(mpq_class(away) - q);
  if (dt < da) return t;
  if (da < dt) return away;
  // A tie: pick the one whose last significand bit is zero.
  int e = 0;
  const double mt = std::frexp(t, &e);
  const double scaled = std::ldexp(mt, std::numeric_limits<double>::digits);
  return (static_cast<long long>(scaled) % 2 == 0) ? t : away;
}

}  // namespace mk
