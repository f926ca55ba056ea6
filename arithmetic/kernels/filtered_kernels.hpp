// IntervalKernel and AdaptiveKernel: exact decisions on input points, crossing points
// constructed and rounded to doubles, as the paper did. [MK89 §3.3] [Sh97]
// Preconditions: finite double input. Decisions on rounded crossings (output assembly only)
// are exact on the rounded coordinates.
#pragma once

#include <string_view>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rounded_crossing_kernel.hpp"

namespace mk {

struct IntervalPredicates {
  static constexpr std::string_view name = "interval";
  static int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return interval_filter::orient2d(ax, ay, bx, by, cx, cy);
  }
  static int orient_vectors(double a, double b, double c, double d, double e, double f, double g, double h) {
    return interval_filter::orient_vectors(a, b, c, d, e, f, g, h);
  }
};

struct AdaptivePredicates {
  static constexpr std::string_view name = "adaptive";
  static int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return adaptive::orient2d(ax, ay, bx, by, cx, cy);
  }
  static int orient_vectors(double a, double b, double c, double d, double e, double f, double g, double h) {
    return adaptive::orient_vectors(a, b, c, d, e, f, g, h);
  }
};

// The paper's approach: interval filter with multiprecision fallback [MK89 §3.3].
using IntervalKernel = RoundedCrossingKernel<IntervalPredicates>;
// Shewchuk's adaptive expansions [Sh97].
using AdaptiveKernel = RoundedCrossingKernel<AdaptivePredicates>;

}  // namespace mk
