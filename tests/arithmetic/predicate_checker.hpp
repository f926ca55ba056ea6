// Runs the exact predicates (adaptive, interval filter, GMP fallback) on one input, compares
// each with the mpq reference and counts disagreements, keeping a few reproducible
// examples. The MPFR interval stages (128 and 256 bits) are run on their own too: when
// they decide, they must agree. The naive double predicate is recorded, never asserted.
// [Sh97] [MK89 §3.3] [MPFR]
// Preconditions: finite inputs.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_reference.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/mpfr_interval.hpp"
#include "arithmetic/predicates_gmp.hpp"
#include "arithmetic/predicates_naive.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace mk::test {

class PredicateChecker {
 public:
  explicit PredicateChecker(std::string name) : name_(std::move(name)) {}

  // Returns the reference sign.
  int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    const int want = reference::orient2d(ax, ay, bx, by, cx, cy);
    const std::array<double, 6> in{ax, ay, bx, by, cx, cy};
    record("orient2d adaptive", adaptive::orient2d(ax, ay, bx, by, cx, cy), want, in, adaptive_);
    record("orient2d interval", interval_filter::orient2d(ax, ay, bx, by, cx, cy), want, in, interval_);
    record("orient2d gmp", gmp::orient2d(ax, ay, bx, by, cx, cy), want, in, gmp_);
    record_stage("orient2d mpfr_128", mpfr_interval::cross_sign<128>(ax, ay, bx, by, ax, ay, cx, cy), want, in,
                 mpfr_128_, mpfr_128_decided_);
    record_stage("orient2d mpfr_256", mpfr_interval::cross_sign<256>(ax, ay, bx, by, ax, ay, cx, cy), want, in,
                 mpfr_256_, mpfr_256_decided_);
    note_naive(naive::orient2d(ax, ay, bx, by, cx, cy), want);
    return want;
  }

  int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                     double q2x, double q2y) {
    const int want = reference::orient_vectors(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
    const std::array<double, 8> in{p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y};
    record("orient_vectors adaptive", adaptive::orient_vectors(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y),
           want, in, adaptive_);
    record("orient_vectors interval",
           interval_filter::orient_vectors(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y), want, in, interval_);
    record("orient_vectors gmp", gmp::orient_vectors(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y), want, in,
           gmp_);
    record_stage("orient_vectors mpfr_128", mpfr_interval::cross_sign<128>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y),
                 want, in, mpfr_128_, mpfr_128_decided_);
    record_stage("orient_vectors mpfr_256", mpfr_interval::cross_sign<256>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y),
                 want, in, mpfr_256_, mpfr_256_decided_);
    note_naive(naive::orient_vectors(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y), want);
    return want;
  }

  // Prints the tallies and fails the current test on any disagreement of an exact method.
  void expect_no_disagreement() const {
    std::cout << name_ << ": " << cases_ << " cases (" << zeros_ << " exact zeros), disagreements with "
              << "mpq: adaptive " << adaptive_ << ", interval " << interval_ << ", gmp " << gmp_
              << ", mpfr_128 " << mpfr_128_ << ", mpfr_256 " << mpfr_256_ << " (of "
              << mpfr_128_decided_ << " and " << mpfr_256_decided_ << " they decided); naive double wrong on "
              << naive_wrong_ << " (recorded, not asserted)\n";
    for (const auto& e : examples_) std::cout << "  " << e << "\n";
    EXPECT_EQ(adaptive_, 0u) << name_;
    EXPECT_EQ(interval_, 0u) << name_;
    EXPECT_EQ(gmp_, 0u) << name_;
    EXPECT_EQ(mpfr_128_, 0u) << name_;
    EXPECT_EQ(mpfr_256_, 0u) << name_;
  }

  std::size_t cases() const { return cases_; }

 private:
  template <std::size_t N>
  void record(const char* what, int got, int want, const std::array<double, N>& in, std::size_t& count) {
    if (got == want) return;
    ++count;
    if (examples_.size() < 10) {
      std::ostringstream s;
      s << what << " got " << got << " want " << want << " at";
      for (const double v : in) s << " " << hex(v);
      examples_.push_back(s.str());
    }
  }
  // A stage that may leave the call undecided (2).
  template <std::size_t N>
  void record_stage(const char* what, int got, int want, const std::array<double, N>& in, std::size_t& count,
                    std::size_t& decided) {
    if (got == 2) return;
    ++decided;
    record(what, got, want, in, count);
  }
  void note_naive(int got, int want) {
    ++cases_;
    if (want == 0) ++zeros_;
    if (got != want) ++naive_wrong_;
  }

  std::string name_;
  std::size_t cases_ = 0;
  std::size_t zeros_ = 0;
  std::size_t adaptive_ = 0;
  std::size_t interval_ = 0;
  std::size_t gmp_ = 0;
  std::size_t mpfr_128_ = 0;
  std::size_t mpfr_256_ = 0;
  std::size_t mpfr_128_decided_ = 0;
  std::size_t mpfr_256_decided_ = 0;
  std::size_t naive_wrong_ = 0;
  std::vector<std::string> examples_;
};

}  // namespace mk::test
