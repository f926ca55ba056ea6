// Correct rounding of exact values to doubles through MPFR: round-to-nearest-even at 53 bits
// in the exponent range of IEEE binary64, subnormals included, overflow to +-infinity.
// [MPFR] (mpfr_set_q, mpfr_subnormalize: "emulating IEEE 754 binary64")
// Preconditions: none. MPFR keeps its exponent range per thread (Debian's build is
// thread-safe); the range is set for the conversion only and restored after it.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <type_traits>

namespace mk {

// Sets MPFR's exponent range to binary64's for the guard's lifetime: with a 53-bit value,
// emin = -1073 and emax = 1024 make mpfr_subnormalize round exactly as IEEE 754 does in the
// subnormal range (MPFR's significands lie in [1/2, 1), so 2^-1074 = 0.5 * 2^-1073).
class DoubleExponentRange {
 public:
  DoubleExponentRange() : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
  }
  ~DoubleExponentRange() {
    mpfr_set_emin(emin_);
    mpfr_set_emax(emax_);
  }
  DoubleExponentRange(const DoubleExponentRange&) = delete;
  DoubleExponentRange& operator=(const DoubleExponentRange&) = delete;

 private:
  mpfr_exp_t emin_;
  mpfr_exp_t emax_;
};

// GMP's rational as an object (mpq_t is an array of one): taken by reference, so that no
// integer literal converts to it, as 0 would to a pointer.
using MpqValue = std::remove_extent_t<mpq_t>;

// The double nearest to q, ties to even; +-infinity when |q| rounds beyond the largest
// double (|q| >= DBL_MAX + ulp/2), as IEEE 754 rounds.
inline double nearest_double(const MpqValue& q) {
  const DoubleExponentRange range;
  mpfr_t x;
  mpfr_init2(x, 53);
  const int inexact = mpfr_set_q(x, &q, MPFR_RNDN);
  mpfr_subnormalize(x, inexact, MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);  // exact: x is a double now
  mpfr_clear(x);
  return d;
}

inline double nearest_double(const mpq_class& q) { return nearest_double(*q.get_mpq_t()); }

}  // namespace mk
