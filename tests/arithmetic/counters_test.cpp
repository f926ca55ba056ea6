// Predicate counters: compiled in here (MK_PREDICATE_COUNTERS), per thread, with reset and
// read; and the stage each kind of input is expected to be decided by. [Sh97 §4.2]
#include "arithmetic/predicates_counters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <thread>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/interval_filter.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace {

using mk::PredicateCounters;
using mk::PredicateKind;
using mk::PredicateMethod;
using mk::PredicateStage;

constexpr auto adaptive = PredicateMethod::adaptive;
constexpr auto interval = PredicateMethod::interval;
constexpr auto orient2d = PredicateKind::orient2d;

std::uint64_t decided(PredicateMethod m, PredicateStage s, PredicateKind k = orient2d) {
  return PredicateCounters::read().decided(m, k, s);
}

void print(const char* what) {
  const auto c = PredicateCounters::read();
  std::cout << what << ": adaptive calls " << c.calls(adaptive, orient2d) << ", decided by";
  for (const auto s : mk::adaptive_stages) std::cout << " " << mk::stage_name(s) << " " << c.decided(adaptive, orient2d, s);
  std::cout << "; interval calls " << c.calls(interval, orient2d) << ", decided by";
  for (const auto s : mk::interval_stages) std::cout << " " << mk::stage_name(s) << " " << c.decided(interval, orient2d, s);
  std::cout << "\n";
}

// Every call is decided by exactly one stage of its method.
void expect_each_call_decided_once() {
  const auto c = PredicateCounters::read();
  for (const auto k : {orient2d, PredicateKind::orient_vectors}) {
    std::uint64_t a = 0, i = 0;
    for (const auto s : mk::adaptive_stages) a += c.decided(adaptive, k, s);
    for (const auto s : mk::interval_stages) i += c.decided(interval, k, s);
    EXPECT_EQ(a, c.calls(adaptive, k));
    EXPECT_EQ(i, c.calls(interval, k));
    EXPECT_LE(c.past_filter(adaptive, k), c.calls(adaptive, k));
    EXPECT_LE(c.past_filter(interval, k), c.calls(interval, k));
  }
}

TEST(arith_counters, compiled_in_reset_and_read) {
  static_assert(PredicateCounters::enabled);
  PredicateCounters::reset();
  EXPECT_EQ(PredicateCounters::read().calls(adaptive, orient2d), 0u);
  mk::adaptive::orient2d(0, 0, 1, 0, 0, 1);
  mk::adaptive::orient_vectors(0, 0, 1, 0, 0, 0, 0, 1);
  mk::interval_filter::orient2d(0, 0, 1, 0, 0, 1);
  const auto c = PredicateCounters::read();
  EXPECT_EQ(c.calls(adaptive, orient2d), 1u);
  EXPECT_EQ(c.calls(adaptive, PredicateKind::orient_vectors), 1u);
  EXPECT_EQ(c.calls(interval, orient2d), 1u);
  EXPECT_EQ(c.decided(adaptive, orient2d, PredicateStage::filter), 1u);
  EXPECT_EQ(c.past_filter(adaptive, orient2d), 0u);
  PredicateCounters::reset();
  EXPECT_EQ(PredicateCounters::read().calls(adaptive, orient2d), 0u);
}

TEST(arith_counters, counters_are_per_thread) {
  PredicateCounters::reset();
  std::uint64_t other = 0;
  std::thread t([&] {
    for (int i = 0; i < 5; ++i) mk::adaptive::orient2d(0, 0, 1, 0, 0, i + 1.0);
    other = PredicateCounters::read().calls(adaptive, orient2d);
  });
  t.join();
  EXPECT_EQ(other, 5u);
  EXPECT_EQ(PredicateCounters::read().calls(adaptive, orient2d), 0u);
}

TEST(arith_counters, random_input_stops_at_the_filter) {
  PredicateCounters::reset();
  std::mt19937_64 rng(4001);
  std::uniform_real_distribution<double> d(-1, 1);
  for (int k = 0; k < 10000; ++k) {
    const double v[6] = {d(rng), d(rng), d(rng), d(rng), d(rng), d(rng)};
    mk::adaptive::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    mk::interval_filter::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
  }
  print("random");
  expect_each_call_decided_once();
  EXPECT_GT(decided(adaptive, PredicateStage::filter), 9990u);
  EXPECT_GT(decided(interval, PredicateStage::filter), 9990u);
}

TEST(arith_counters, collinear_input_reaches_the_expected_stages) {
  // Exact differences: stage B decides (all tails zero); every interval operation is exact
  // too, and the enclosure [0, 0] proves the zero without MPFR or GMP.
  PredicateCounters::reset();
  for (int k = 1; k <= 100; ++k) {
    mk::adaptive::orient2d(0.25 * k, 0.75 * k, 3.0 * k, 9.0 * k, 7.0 * k, 21.0 * k);
    mk::interval_filter::orient2d(0.25 * k, 0.75 * k, 3.0 * k, 9.0 * k, 7.0 * k, 21.0 * k);
  }
  print("collinear, exact differences");
  expect_each_call_decided_once();
  EXPECT_EQ(decided(adaptive, PredicateStage::expansion_b), 100u);
  EXPECT_EQ(decided(interval, PredicateStage::interval), 100u);

  // Inexact differences (points of different binades on y = x/3), each axis within 2^69:
  // adaptive's exact stage decides in fixed point, without stages C or GMP. The interval
  // stage on doubles cannot prove a zero whose differences are rounded; the MPFR stages
  // decide each call whose differences fit their precision (mpfr_interval.hpp): values of
  // 45 bits with exponents in [-30, 32] make differences of at most 62 + 47 bits, so 128
  // bits always suffice.
  PredicateCounters::reset();
  std::mt19937_64 rng(4002);
  for (int k = 0; k < 1000; ++k) {
    const double a = mk::test::random_short_double(rng, 45, -30, 30);
    const double b = mk::test::random_short_double(rng, 45, -30, 30);
    const double c = mk::test::random_short_double(rng, 45, -30, 30);
    EXPECT_EQ(mk::adaptive::orient2d(3 * a, a, 3 * b, b, 3 * c, c), 0);
    EXPECT_EQ(mk::interval_filter::orient2d(3 * a, a, 3 * b, b, 3 * c, c), 0);
  }
  print("collinear, inexact differences");
  expect_each_call_decided_once();
  EXPECT_GT(decided(adaptive, PredicateStage::fixed_point), 900u);
  EXPECT_EQ(decided(adaptive, PredicateStage::expansion_c), 0u);
  EXPECT_EQ(decided(adaptive, PredicateStage::gmp), 0u);
  EXPECT_EQ(decided(interval, PredicateStage::mpfr_128), 1000u);

  // The same with axes spanning up to 2^100: too wide for fixed point, so stages C and the
  // exact expansion stage; differences of up to 102 + 47 bits, some past 128 bits, none
  // past 256.
  PredicateCounters::reset();
  for (int k = 0; k < 1000; ++k) {
    const double a = mk::test::random_short_double(rng, 45, -50, 50);
    const double b = mk::test::random_short_double(rng, 45, -50, 50);
    const double c = mk::test::random_short_double(rng, 45, -50, 50);
    EXPECT_EQ(mk::adaptive::orient2d(3 * a, a, 3 * b, b, 3 * c, c), 0);
    EXPECT_EQ(mk::interval_filter::orient2d(3 * a, a, 3 * b, b, 3 * c, c), 0);
  }
  print("collinear, inexact differences, wide axes");
  expect_each_call_decided_once();
  EXPECT_GT(decided(interval, PredicateStage::mpfr_128), 0u);
  EXPECT_GT(decided(interval, PredicateStage::mpfr_256), 0u);
  EXPECT_EQ(decided(interval, PredicateStage::gmp), 0u);
  EXPECT_GT(decided(adaptive, PredicateStage::expansion_exact), 0u);
  EXPECT_EQ(decided(adaptive, PredicateStage::gmp), 0u);

  // Magnitudes too far apart for expansions: GMP. For the interval stages, a difference
  // 1e300 - 1e-300 needs about 2050 bits: no MPFR stage is exact, so GMP decides the zero.
  PredicateCounters::reset();
  EXPECT_EQ(mk::adaptive::orient2d(1e-300, 1e-300, 1e300, 1e300, -1e300, -1e300), 0);
  EXPECT_EQ(mk::interval_filter::orient2d(1e-300, 1e-300, 1e300, 1e300, -1e300, -1e300), 0);
  expect_each_call_decided_once();
  EXPECT_EQ(decided(adaptive, PredicateStage::gmp), 1u);
  EXPECT_EQ(decided(interval, PredicateStage::gmp), 1u);
  // Huge, each axis within 2^69 of its largest input: the fixed-point stage, no GMP.
  PredicateCounters::reset();
  EXPECT_EQ(mk::adaptive::orient2d(1e300, 1e300, 1.5e300, 1.5e300, 1.7e308, 1.7e308), 0);
  print("huge");
  EXPECT_EQ(decided(adaptive, PredicateStage::fixed_point), 1u);
  EXPECT_EQ(PredicateCounters::read().past_filter(adaptive, orient2d), 1u);
}

}  // namespace
