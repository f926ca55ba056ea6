// Ground truth for the predicates on doubles: the formula of arithmetic/formulas.hpp
// evaluated in GMP rationals, which hold every finite double exactly. [MK89 §3.3] [Sh97]
// Preconditions: finite inputs (mpq_set_d is exact for every finite double, subnormals
// included; NaN and infinities are not numbers it can hold).
// Used by tests as the reference; slow (a few rational operations with gcds per call).
#pragma once

#include <gmpxx.h>

#include "arithmetic/formulas.hpp"

namespace mk::reference {

// (b - a) x (c - a), exactly.
inline mpq_class orient2d_value(double ax, double ay, double bx, double by, double cx, double cy) {
  return formula::orient2d<mpq_class>(mpq_class(ax), mpq_class(ay), mpq_class(bx), mpq_class(by),
                                      mpq_class(cx), mpq_class(cy));
}

// (q1 - p1) x (q2 - p2), exactly.
inline mpq_class orient_vectors_value(double p1x, double p1y, double q1x, double q1y, double p2x,
                                      double p2y, double q2x, double q2y) {
  return formula::cross_of_differences<mpq_class>(mpq_class(p1x), mpq_class(p1y), mpq_class(q1x),
                                                  mpq_class(q1y), mpq_class(p2x), mpq_class(p2y),
                                                  mpq_class(q2x), mpq_class(q2y));
}

inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return sgn(orient2d_value(ax, ay, bx, by, cx, cy));
}

inline int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                          double q2x, double q2y) {
  return sgn(orient_vectors_value(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y));
}

}  // namespace mk::reference
