// DoubleKernel: plain floating point everywhere; crossing points rounded. The naive baseline:
// its failures are data for the experiments and are never patched in the core.
// [MK89 §3.3] (the paper's warning about ordinary floating point) [KMPSY08]
// Preconditions: finite double input.
#pragma once

#include <string_view>

#include "arithmetic/kernels/rounded_crossing_kernel.hpp"
#include "arithmetic/predicates_naive.hpp"

namespace mk {

// The formula evaluated once in double (arithmetic/predicates_naive.hpp).
struct NaivePredicates {
  static constexpr std::string_view name = "double";
  static int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return naive::orient2d(ax, ay, bx, by, cx, cy);
  }
  static int orient_vectors(double a, double b, double c, double d, double e, double f, double g, double h) {
    return naive::orient_vectors(a, b, c, d, e, f, g, h);
  }
};

using DoubleKernel = RoundedCrossingKernel<NaivePredicates>;

}  // namespace mk
