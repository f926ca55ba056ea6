// Tests of the error-free transformations and expansion algorithms against exact
// rationals: every result must equal its exact value and stay nonoverlapping. [Sh97 §2]
#include "arithmetic/expansion.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "tests/arithmetic/test_support.hpp"

namespace {

using mk::test::exact;
using mk::test::hex;
using mk::test::random_double;
namespace ex = mk::expansion;

constexpr std::uint64_t seed = 20260101;

// The lowest set bit of a non-zero double, as a power of two.
double lowest_bit(double v) {
  int e = 0;
  const double f = std::frexp(std::fabs(v), &e);
  auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  int shift = 0;
  while ((m & 1u) == 0) {
    m >>= 1;
    ++shift;
  }
  return std::ldexp(1.0, e - 53 + shift);
}

// Components in increasing magnitude, no two overlapping [Sh97 §2.3].
bool is_nonoverlapping(std::span<const double> e) {
  double previous = 0.0;
  for (const double c : e) {
    if (c == 0.0) continue;
    if (previous != 0.0 && !(std::fabs(previous) < lowest_bit(c))) return false;
    previous = c;
  }
  return true;
}

TEST(arith_expansion, error_free_transformations_are_exact) {
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 200000; ++k) {
    // Exponents within +-450 keep a product's error term above 2^-1074 (representable).
    const double a = random_double(rng, -450, 450);
    const double b = random_double(rng, -450, 450);
    const auto s = ex::two_sum(a, b);
    ASSERT_EQ(exact(s.hi) + exact(s.lo), exact(a) + exact(b)) << hex(a) << " " << hex(b);
    ASSERT_EQ(s.hi, a + b);
    const auto d = ex::two_diff(a, b);
    ASSERT_EQ(exact(d.hi) + exact(d.lo), exact(a) - exact(b)) << hex(a) << " " << hex(b);
    const auto p = ex::two_product(a, b);
    ASSERT_EQ(exact(p.hi) + exact(p.lo), exact(a) * exact(b)) << hex(a) << " " << hex(b);
    const double big = std::fabs(a) >= std::fabs(b) ? a : b;
    const double small = std::fabs(a) >= std::fabs(b) ? b : a;
    const auto f = ex::fast_two_sum(big, small);
    ASSERT_EQ(exact(f.hi) + exact(f.lo), exact(a) + exact(b)) << hex(a) << " " << hex(b);
  }
}

// Dekker's product within its documented range: operands that are multiples of 2^-511,
// at most 2^996, with a product at most 2^1021. Random operands over the whole range, then
// the corners: the smallest operands (full 53-bit mantissas ending at 2^-511, so the error
// term ends at 2^-1022), the largest operand against factors that keep the product below
// 2^1021, and operands whose split parts round up (mantissas of all ones).
TEST(arith_expansion, two_product_split_is_exact_in_its_range) {
  std::mt19937_64 rng(seed + 10);
  auto check = [](double a, double b) {
    const auto p = ex::two_product_split(a, b);
    ASSERT_EQ(p.hi, a * b) << hex(a) << " " << hex(b);
    ASSERT_EQ(exact(p.hi) + exact(p.lo), exact(a) * exact(b)) << hex(a) << " " << hex(b);
  };
  // A random multiple of 2^-511 with up to 53 significant bits and magnitude in
  // [2^e_min, 2^(e_max + 1)).
  auto operand = [&](int e_min, int e_max) {
    const double v = random_double(rng, e_min, e_max);
    const double grid = std::ldexp(1.0, -511);
    return std::trunc(v / grid) * grid;
  };
  for (int k = 0; k < 300000; ++k) {
    const double a = operand(-511, 995);
    const double b = operand(-511, 995);
    if (std::fabs(a * b) <= std::ldexp(1.0, 1021)) check(a, b);
    if (std::fabs(a * a) <= std::ldexp(1.0, 1021)) check(a, a);
  }
  const double all_ones = std::ldexp(1.0, 53) - 1.0;  // 53 set bits
  const std::array<double, 6> low{std::ldexp(all_ones, -511), std::ldexp(1.0, -511), std::ldexp(all_ones - 2, -511),
                                  std::ldexp(3.0, -511), std::ldexp(all_ones, -480), std::ldexp(0x1.5555555555555p0, -458)};
  const std::array<double, 5> high{std::ldexp(1.0, 996), std::ldexp(all_ones, 943), std::ldexp(all_ones, 900),
                                   std::ldexp(0x1.fffffffp0, 995), std::ldexp(0x1.0000001p0, 995)};
  for (const double a : low) {
    for (const double b : low) {
      check(a, b);
      check(-a, b);
    }
    for (const double b : high) check(a, -b);
  }
  for (const double a : high) {
    for (const double b : {std::ldexp(all_ones, -28), std::ldexp(1.0, 25), std::ldexp(all_ones, 20), 0.75, -1.0}) {
      if (std::fabs(a * b) <= std::ldexp(1.0, 1021)) check(a, b);
    }
  }
  check(0.0, std::ldexp(1.0, 996));
  check(-0.0, std::ldexp(all_ones, -511));
}

TEST(arith_expansion, sums_of_subnormals_are_exact) {
  // Addition never loses bits below 2^-1022, so two_sum stays exact there.
  std::mt19937_64 rng(seed + 1);
  for (int k = 0; k < 100000; ++k) {
    const double a = random_double(rng, -1074, -1000);
    const double b = random_double(rng, -1074, -1000);
    const auto s = ex::two_sum(a, b);
    ASSERT_EQ(exact(s.hi) + exact(s.lo), exact(a) + exact(b)) << hex(a) << " " << hex(b);
  }
}

TEST(arith_expansion, two_two_diff_is_exact_and_nonoverlapping) {
  std::mt19937_64 rng(seed + 2);
  for (int k = 0; k < 200000; ++k) {
    const auto l = ex::two_product(random_double(rng, -200, 200), random_double(rng, -200, 200));
    const auto r = ex::two_product(random_double(rng, -200, 200), random_double(rng, -200, 200));
    const auto b = ex::two_two_diff(l.hi, l.lo, r.hi, r.lo);
    const mpq_class want = exact(l.hi) + exact(l.lo) - exact(r.hi) - exact(r.lo);
    ASSERT_EQ(exact(b), want);
    ASSERT_TRUE(is_nonoverlapping(b));
    ASSERT_EQ(ex::sign(b), sgn(want));
  }
}

// A random expansion of up to 4 * terms components, built the way the predicates build
// theirs: exact differences of products, summed with expansion_sum.
std::vector<double> random_expansion(std::mt19937_64& rng, int terms, int e_lo, int e_hi) {
  std::vector<double> e{0.0};
  for (int t = 0; t < terms; ++t) {
    const auto l = ex::two_product(random_double(rng, e_lo, e_hi), random_double(rng, e_lo, e_hi));
    const auto r = ex::two_product(random_double(rng, e_lo, e_hi), random_double(rng, e_lo, e_hi));
    const auto u = ex::two_two_diff(l.hi, l.lo, r.hi, r.lo);
    std::vector<double> h(e.size() + u.size());
    h.resize(ex::expansion_sum(e, u, h));
    e = h;
  }
  return e;
}

TEST(arith_expansion, expansion_sum_is_exact_and_nonoverlapping) {
  std::mt19937_64 rng(seed + 3);
  for (int k = 0; k < 20000; ++k) {
    const auto e = random_expansion(rng, 1 + k % 4, -60, 60);
    const auto f = random_expansion(rng, 1 + k % 3, -90, 30);
    std::vector<double> h(e.size() + f.size());
    h.resize(ex::expansion_sum(e, f, h));
    ASSERT_EQ(exact(h), exact(e) + exact(f));
    ASSERT_TRUE(is_nonoverlapping(h));
    ASSERT_EQ(ex::sign(h), sgn(exact(h)));
  }
}

TEST(arith_expansion, expansion_sum_cancels_to_a_single_zero) {
  std::mt19937_64 rng(seed + 4);
  const auto e = random_expansion(rng, 3, -40, 40);
  std::vector<double> minus_e;
  for (const double c : e) minus_e.push_back(-c);
  std::vector<double> h(e.size() * 2);
  h.resize(ex::expansion_sum(e, minus_e, h));
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0], 0.0);
  EXPECT_EQ(ex::sign(h), 0);
}

TEST(arith_expansion, grow_expansion_is_exact_and_nonoverlapping) {
  std::mt19937_64 rng(seed + 5);
  for (int k = 0; k < 20000; ++k) {
    std::vector<double> e{random_double(rng, -100, 100)};
    mpq_class want = exact(e[0]);
    for (int t = 0; t < 12; ++t) {
      const double b = random_double(rng, -100, 100);
      std::vector<double> h(e.size() + 1);
      h.resize(ex::grow_expansion(e, b, h));
      want += exact(b);
      ASSERT_EQ(exact(h), want);
      ASSERT_TRUE(is_nonoverlapping(h));
      e = h;
    }
  }
}

TEST(arith_expansion, scale_expansion_is_exact_and_nonoverlapping) {
  std::mt19937_64 rng(seed + 6);
  for (int k = 0; k < 20000; ++k) {
    const auto e = random_expansion(rng, 1 + k % 4, -60, 60);
    const double b = random_double(rng, -60, 60);
    std::vector<double> h(2 * e.size());
    h.resize(ex::scale_expansion(e, b, h));
    ASSERT_EQ(exact(h), exact(e) * exact(b));
    ASSERT_TRUE(is_nonoverlapping(h));
  }
}

TEST(arith_expansion, compress_keeps_the_value_and_approximates_it_by_its_top) {
  std::mt19937_64 rng(seed + 7);
  for (int k = 0; k < 20000; ++k) {
    const auto e = random_expansion(rng, 1 + k % 4, -60, 60);
    std::vector<double> h(e.size());
    h.resize(ex::compress(e, h));
    ASSERT_LE(h.size(), e.size());
    ASSERT_EQ(exact(h), exact(e));
    ASSERT_TRUE(is_nonoverlapping(h));
    // [Sh97 §2.8] after compression the largest component is within one ulp of the value.
    const double top = h.back();
    if (top != 0.0) {
      const mpq_class error = abs(exact(h) - exact(top));
      const double ulp = std::nextafter(std::fabs(top), HUGE_VAL) - std::fabs(top);
      ASSERT_LE(error, exact(ulp));
    }
    // In place, as the paper allows.
    std::vector<double> in_place = e;
    in_place.resize(ex::compress(in_place, in_place));
    ASSERT_EQ(in_place, h);
  }
}

TEST(arith_expansion, estimate_is_close_and_sign_is_exact) {
  std::mt19937_64 rng(seed + 8);
  for (int k = 0; k < 20000; ++k) {
    const auto e = random_expansion(rng, 1 + k % 4, -60, 60);
    const mpq_class value = exact(e);
    EXPECT_EQ(ex::sign(e), sgn(value));
    const double approx = ex::estimate(e);
    EXPECT_LE(abs(exact(approx) - value), abs(value) * mpq_class(1, 1u << 20) + mpq_class(0));
  }
}

}  // namespace
