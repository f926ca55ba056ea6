// The only place where mkbool changes the floating-point rounding mode: an RAII guard that
// sets a mode and restores the caller's on every exit path. [BMP06] (Boost.Interval,
// directed rounding) [MK89 §3.3] (interval filter)
// Preconditions: the C floating-point environment controls the rounding of double
// arithmetic (true on x86-64 with SSE2, where Boost.Interval also uses fesetround); code
// that runs inside the guard takes its inputs through opaque() and hands its results out
// through volatile objects (Boost.Interval's force_rounding does), so that the compiler
// neither evaluates them under the caller's mode nor folds them at compile time.
#pragma once

#include <cfenv>

namespace mk {

class RoundingGuard {
 public:
  // mode: FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO or FE_TONEAREST.
  explicit RoundingGuard(int mode) : saved_(std::fegetround()) { std::fesetround(mode); }
  ~RoundingGuard() { std::fesetround(saved_); }
  RoundingGuard(const RoundingGuard&) = delete;
  RoundingGuard& operator=(const RoundingGuard&) = delete;

  // v, passed through a volatile object. The compiler sees fesetround as an opaque call and
  // keeps volatile accesses in program order around it, so every operation on the result
  // happens after the mode change. Without this it may reuse a value computed under the
  // caller's mode (common subexpressions) or fold constant inputs with round-to-nearest.
  static double opaque(double v) {
    volatile double sink = v;
    return sink;
  }

 private:
  int saved_;
};

}  // namespace mk
