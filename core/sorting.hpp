// Sorting by a kernel's predicates. An exact kernel's comparisons are consistent and
// std::sort serves; an inexact kernel's may not be (a naive kernel's products overflow to
// infinity or NaN near 1e300, rounded crossings compare inconsistently), and std::sort's
// unguarded insertion then runs past the range (a crash seen at 1e300 with kernel `double`).
// A heap sort's index arithmetic stays inside the range whatever the comparison answers: the
// order may be wrong, as the kernel's answers are, but nothing is read or written outside.
// [BRIEF §8] (bad input: never a crash)
// Preconditions: none on `less` for inexact kernels; a strict weak order for exact ones.
#pragma once

#include <algorithm>

#include "kernel/kernel.hpp"

namespace mk {

template <Kernel K, class It, class Less>
void sort_by_predicates(It first, It last, Less&& less) {
  if constexpr (K::is_exact) {
    std::sort(first, last, less);
  } else {
    std::make_heap(first, last, less);
    std::sort_heap(first, last, less);
  }
}

}  // namespace mk
