// An exact running sum of doubles and of products of doubles, kept as a compressed
// expansion in a fixed buffer: the shoelace sums of the areas add millions of terms, each
// in a few two-sums on a sum of a handful of components. [Sh97 §2] (GROW-EXPANSION,
// COMPRESS, error-free products)
// Preconditions: every added value and product is finite and the running sum never
// overflows; add_product needs is_exact_product(a, b) (the caller checks, or accounts for
// the error). Round-to-nearest-even, no flush-to-zero, -ffp-contract=off (mkbool_arith).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "arithmetic/expansion.hpp"

namespace mk {

class ExactAccumulator {
 public:
  // Adds b exactly (GROW-EXPANSION in place: each roundoff is written at or below the
  // component it came from, so nothing unread is overwritten).
  void add(double b) {
    if (b == 0.0) return;
    double q = b;
    std::size_t k = 0;
    for (std::size_t i = 0; i < n_; ++i) {
      const expansion::TwoTerm s = expansion::two_sum(q, e_[i]);
      q = s.hi;
      e_[k] = s.lo;
      k += s.lo != 0.0;
    }
    if (q != 0.0) e_[k++] = q;
    n_ = k;
    if (n_ > kCompressAt) n_ = expansion::compress(view(), room());
  }

  // Adds a * b exactly, by Dekker's product; a and b are safe factors (is_safe_factor).
  void add_product(double a, double b) {
    const expansion::TwoTerm p = expansion::two_product_split(a, b);
    add(p.lo);
    add(p.hi);
  }

  // The sum, compressed: its largest component is the sum to within one ulp.
  std::span<const double> value() {
    if (n_ > 1) n_ = expansion::compress(view(), room());
    if (n_ == 0) e_[n_++] = 0.0;
    return view();
  }

  // Whether v can be a factor of add_product with any other such factor: zero, or at most
  // 2^498 in magnitude and a multiple of 2^-511. Two such factors meet the preconditions
  // of Dekker's product (expansion::two_product_split): no step overflows or underflows.
  static bool is_safe_factor(double v) {
    if (v == 0.0) return true;
    if (!(std::fabs(v) <= 0x1p498)) return false;
    if (std::fabs(v) >= 0x1p-458) return true;  // its last place is 2^-510 or above
    return std::fmod(v, 0x1p-511) == 0.0;
  }

 private:
  static constexpr std::size_t kCapacity = 64;
  static constexpr std::size_t kCompressAt = kCapacity - 8;
  std::span<const double> view() const { return {e_.data(), n_}; }
  std::span<double> room() { return {e_.data(), kCapacity}; }

  std::array<double, kCapacity> e_;
  std::size_t n_ = 0;
};

}  // namespace mk
