// Re-derives every filter error bound from its formula and checks, in exact rational
// arithmetic, the inequalities that make it valid (adaptive_bounds.hpp (A3), (A4), (B2),
// (C2), (C3); interval_filter.hpp (S1)) and the range arguments. [Sh97 §4.2-4.3]
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cfloat>
#include <cmath>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/adaptive_bounds.hpp"
#include "arithmetic/interval_filter.hpp"

namespace {

// 2^k exactly.
mpq_class power_of_two(int k) {
  mpq_class r = 1;
  if (k >= 0) mpz_mul_2exp(r.get_num_mpz_t(), r.get_num_mpz_t(), static_cast<mp_bitcnt_t>(k));
  else mpz_mul_2exp(r.get_den_mpz_t(), r.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-k));
  r.canonicalize();
  return r;
}

mpq_class pow(const mpq_class& x, int n) {
  mpq_class r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

const mpq_class u = power_of_two(-53);
const mpq_class eta = power_of_two(-1075);
const mpq_class one = 1;
const mpq_class theta = 3 * u + 3 * u * u + u * u * u;

// Evaluated at run time from a volatile epsilon, so the compiler cannot reuse the constexpr.
TEST(arith_bounds, constants_match_their_formulas) {
  volatile double eps_in = std::ldexp(1.0, -53);
  const double eps = eps_in;
  EXPECT_EQ(mk::adaptive::epsilon, eps);
  EXPECT_EQ(mk::adaptive::epsilon, DBL_EPSILON / 2);
  EXPECT_EQ(mk::adaptive::bound_a, (3.0 + 16.0 * eps) * eps);
  EXPECT_EQ(mk::adaptive::bound_b, (2.0 + 12.0 * eps) * eps);
  EXPECT_EQ(mk::adaptive::bound_c, (12.0 + 64.0 * eps) * eps * eps);
  EXPECT_EQ(mk::adaptive::bound_c_result, (3.0 + 8.0 * eps) * eps);
  EXPECT_EQ(mk::interval_filter::semi_static_bound, (6.0 + 40.0 * eps) * eps);
  EXPECT_EQ(mk::adaptive::bound_a_floor, DBL_MIN);
  EXPECT_EQ(mk::adaptive::safe_min, std::ldexp(1.0, -400));
  EXPECT_EQ(mk::adaptive::safe_max, std::ldexp(1.0, 500));
  EXPECT_EQ(mk::interval_filter::semi_static_floor, DBL_MIN);
}

TEST(arith_bounds, constants_are_their_formulas_without_rounding) {
  // Each (k + j u) u is exactly representable, so the double is the real constant.
  EXPECT_EQ(mpq_class(mk::adaptive::bound_a), (3 + 16 * u) * u);
  EXPECT_EQ(mpq_class(mk::adaptive::bound_b), (2 + 12 * u) * u);
  EXPECT_EQ(mpq_class(mk::adaptive::bound_c), (12 + 64 * u) * u * u);
  EXPECT_EQ(mpq_class(mk::adaptive::bound_c_result), (3 + 8 * u) * u);
  EXPECT_EQ(mpq_class(mk::interval_filter::semi_static_bound), (6 + 40 * u) * u);
}

TEST(arith_bounds, stage_a_bound_is_valid) {
  const mpq_class a = mk::adaptive::bound_a;
  EXPECT_GE(a * (one - u) / pow(one + u, 3), theta) << "(A3)";
  // Shewchuk's constant has u^2 to spare; a smaller one would not do.
  EXPECT_LT((3 + 12 * u) * u * (one - u) / pow(one + u, 3), theta);
  const mpq_class floor = mk::adaptive::bound_a_floor;
  EXPECT_GE((floor - eta) * (one - u) / (one + u), 2 * pow(one + u, 2) * eta) << "(A4)";
}

TEST(arith_bounds, stage_b_bound_is_valid) {
  const mpq_class b = mk::adaptive::bound_b;
  EXPECT_GE(b * (one - u - u * u - 4 * pow(u, 3)) / pow(one + u, 2), 2 * u + 5 * u * u + 16 * pow(u, 3))
      << "(B2)";
}

TEST(arith_bounds, stage_c_bounds_are_valid) {
  const mpq_class c = mk::adaptive::bound_c;
  const mpq_class r = mk::adaptive::bound_c_result;
  EXPECT_GE(c / pow(one + u, 3), 11 * u * u + 40 * pow(u, 3)) << "(C2)";
  EXPECT_GE(r / pow(one + u, 2), 2 * u + 2 * u * u + 8 * pow(u, 3)) << "(C3)";
}

TEST(arith_bounds, semi_static_bound_is_valid) {
  const mpq_class c = mk::interval_filter::semi_static_bound;
  EXPECT_GE(c * (one - u) / pow(one + u, 3), 2 * theta * (one + u)) << "(S1)";
  const mpq_class floor = mk::interval_filter::semi_static_floor;
  EXPECT_GE((floor - eta * (one + c / (one + u))) * (one - u) / (one + u), (2 * theta + 2 * pow(one + u, 2)) * eta)
      << "(S2)";
  // The leading coefficient 6 cannot be lowered: 2 theta is 6u + O(u^2).
  EXPECT_LT(mpq_class(6) * u * (one - u) / pow(one + u, 3), 2 * theta * (one + u));
}

TEST(arith_bounds, safe_range_keeps_the_expansion_stages_normal_and_finite) {
  // Inputs of magnitude >= 2^-400 are multiples of 2^-452; their products, 2^-904.
  const int granularity = std::ilogb(mk::adaptive::safe_min) - 52;
  EXPECT_EQ(granularity, -452);
  const mpq_class smallest_nonzero = power_of_two(2 * granularity);
  EXPECT_GE(smallest_nonzero, mpq_class(DBL_MIN));
  // The smallest bound product, bound_c * s with s >= 2^-904, is normal.
  EXPECT_GE(mpq_class(mk::adaptive::bound_c) * smallest_nonzero / (one + u), mpq_class(DBL_MIN));
  EXPECT_GE(mpq_class(mk::adaptive::bound_c_result) * smallest_nonzero / (one + u), mpq_class(DBL_MIN));
  // Differences <= 2^501, products <= 2^1003, 16 components <= 2^1008: far from overflow.
  const mpq_class diff = 2 * mpq_class(mk::adaptive::safe_max);
  EXPECT_LT(16 * diff * diff * pow(one + u, 4), mpq_class(DBL_MAX));
}

// fit_into_safe_range scales inputs whose magnitudes span up to 899 binades into
// [safe_min, safe_max] by one power of two (exact, every ratio kept), and refuses a span of
// 900: the limit the argument above relies on, checked at both sides and across the range.
TEST(arith_bounds, fit_into_safe_range_takes_spans_up_to_899_binades) {
  using mk::adaptive::detail::CrossInput;
  using mk::adaptive::detail::fit_into_safe_range;
  for (const int top : {1023, 900, 500, 0, -100, -174}) {
    for (const int span : {0, 1, 600, 899, 900, 1000}) {
      const int bottom = top - span;
      if (bottom < -1074) continue;
      const double large = std::ldexp(1.5, top), small = -std::ldexp(1.25, bottom);  // ilogb: top, bottom
      CrossInput in{large, small, 0.0, -small, -large, large, small, 0.0};
      const CrossInput before = in;
      const bool fits = fit_into_safe_range(in);
      const bool in_range = std::fabs(large) <= mk::adaptive::safe_max && std::fabs(small) >= mk::adaptive::safe_min;
      EXPECT_EQ(fits, span <= 899 || in_range) << "top " << top << " span " << span;
      if (!fits) continue;
      const double* a = &before.p1x;
      const double* b = &in.p1x;
      for (int i = 0; i < 8; ++i) {
        if (b[i] == 0) {
          EXPECT_EQ(a[i], 0);
          continue;
        }
        EXPECT_GE(std::fabs(b[i]), mk::adaptive::safe_min) << "top " << top << " span " << span << " input " << i;
        EXPECT_LE(std::fabs(b[i]), mk::adaptive::safe_max) << "top " << top << " span " << span << " input " << i;
        // One power of two for all: the ratio to the first input is unchanged, exactly.
        EXPECT_EQ(mpq_class(b[i]) / mpq_class(b[0]), mpq_class(a[i]) / mpq_class(a[0]));
      }
    }
  }
}

}  // namespace
