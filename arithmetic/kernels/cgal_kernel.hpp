// CgalKernel: CGAL's filtered predicates (Exact_predicates_inexact_constructions_kernel) as
// the external baseline; crossing points rounded to doubles. [MK89 §3.3]
// Preconditions: finite double input; built only when CGAL is found (MK_WITH_CGAL).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include <string_view>

#include "arithmetic/kernels/rounded_crossing_kernel.hpp"

namespace mk {

struct CgalPredicates {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  static constexpr std::string_view name = "cgal";

  // CGAL's Orientation and Comparison_result are both CGAL::Sign.
  static int from(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

  static int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return from(CGAL::orientation(Epick::Point_2(ax, ay), Epick::Point_2(bx, by), Epick::Point_2(cx, cy)));
  }
  // a - b into d; whether d is exact (Knuth's two-sum error is zero) and finite.
  static bool exact_difference(double a, double b, double& d) {
    d = a - b;
    const double bv = a - d;
    const double av = d + bv;
    return (a - av) + (bv - b) == 0.0 && std::isfinite(d);
  }
  // (q1 - p1) x (q2 - p2) by Epick's filtered vector orientation when the four differences
  // are exact doubles, else with CGAL's exact number type.
  static int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x,
                            double q2y) {
    double x1, y1, x2, y2;
    if (exact_difference(q1x, p1x, x1) && exact_difference(q1y, p1y, y1) && exact_difference(q2x, p2x, x2) &&
        exact_difference(q2y, p2y, y2)) {
      return from(CGAL::orientation(Epick::Vector_2(x1, y1), Epick::Vector_2(x2, y2)));
    }
    using ET = CGAL::Exact_predicates_exact_constructions_kernel::FT;
    const ET d = (ET(q1x) - ET(p1x)) * (ET(q2y) - ET(p2y)) - (ET(q1y) - ET(p1y)) * (ET(q2x) - ET(p2x));
    return from(CGAL::compare(d, ET(0)));
  }
};

using CgalKernel = RoundedCrossingKernel<CgalPredicates>;

}  // namespace mk
