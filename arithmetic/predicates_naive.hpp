// The naive predicates: the formula of arithmetic/formulas.hpp evaluated once in double.
// The baseline whose wrong signs the classroom grids count. [KMPSY08] [MK89 §3.3]
// Preconditions: none; the result is a rounded guess, wrong near degeneracy, and
// meaningless when intermediate results overflow or underflow.
#pragma once

#include "arithmetic/formulas.hpp"

namespace mk::naive {

inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double det = formula::orient2d<double>(ax, ay, bx, by, cx, cy);
  return (det > 0.0) - (det < 0.0);
}

inline int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                          double q2x, double q2y) {
  const double det = formula::cross_of_differences<double>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
  return (det > 0.0) - (det < 0.0);
}

}  // namespace mk::naive
