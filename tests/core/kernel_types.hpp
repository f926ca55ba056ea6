// The kernels as GoogleTest type lists, so that typed suites run every kernel of a kind:
// add a kernel here and every typed suite runs it. [MK89 §3.3]
#pragma once

#include <gtest/gtest.h>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/filtered_kernels.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/kernels/rational_mp_kernels.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif

namespace mk::test {

// Exact kernels other than the reference RationalKernel (mpq_class): each must equal it.
using ExactKernelTypes = ::testing::Types<ExactKernel, RationalMpKernel, RationalCppKernel>;

// Kernels with rounded crossing points: their results are recorded, never asserted.
#ifdef MK_WITH_CGAL
using RoundedKernelTypes = ::testing::Types<DoubleKernel, IntervalKernel, AdaptiveKernel, CgalKernel>;
#else
using RoundedKernelTypes = ::testing::Types<DoubleKernel, IntervalKernel, AdaptiveKernel>;
#endif

// A readable test name per kernel: its `name`.
struct KernelName {
  template <class K>
  static std::string GetName(int) {
    std::string n(K::name);
    for (char& c : n) c = c == '-' ? '_' : c;
    return n;
  }
};

}  // namespace mk::test
