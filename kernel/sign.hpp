// The sign of a predicate: the only answer the algorithm takes from geometry.
// [MK89 §2.1] (east, west or on a directed line)
// Preconditions: none.
#pragma once

namespace mk {

enum class Sign : signed char { negative = -1, zero = 0, positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }

template <class T>
constexpr Sign sign_of(const T& v) {
  return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

}  // namespace mk
