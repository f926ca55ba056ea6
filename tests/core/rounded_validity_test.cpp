// The validity check of rounded output (core/to_output.hpp): the check restricted to the
// edges at crossing points, used when there are few of them, gives the same verdict as the
// full sweep on every random result, valid or not; and both catch hand-made invalid
// roundings. [MK89 §3.3] (detecting non-orientable rounded output)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"
#include "core/to_output.hpp"
#include "tests/core/rounding_cases.hpp"

namespace mk {
namespace {

using test::random_triangle;
using test::round_result;

// Full check: the general function over the rounded rings (sort, sweep).
bool full_check(const std::vector<std::vector<Point>>& rounded) { return is_valid_rounded_output<ExactKernel>(rounded); }

TEST(RoundedValidity, LocalCheckAgreesWithTheFullSweep) {
  const char* env = std::getenv("MK_TEST_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 10) : 17;
  std::printf("seed %llu (set MK_TEST_SEED to change)\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  int valid = 0, invalid = 0;
  for (int i = 0; i < 3000; ++i) {
    const bool degenerate = i % 2 == 0;
    const Polygon a = random_triangle(rng, degenerate);
    const Polygon b = random_triangle(rng, degenerate);
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::symmetric_difference}) {
      Options opt;
      opt.op = op;
      opt.regular = i % 3 != 0;
      BooleanResult<ExactKernel> r;
      try {
        r = boolean_op<ExactKernel>(a, b, opt);
      } catch (const InvalidInput&) {
        continue;  // a triangle collapsed to a segment
      }
      const auto rounded = round_result(r);
      const bool full = full_check(rounded);
      const auto local = detail::are_valid_where_rounded<ExactKernel, ExactKernel>(r, rounded, 1000);
      ASSERT_TRUE(local.has_value());
      ASSERT_EQ(*local, full) << "case " << i << " op " << operation_name(op);
      EXPECT_EQ((is_valid_rounded_result<ExactKernel, ExactKernel>(r, rounded)), full);
      (full ? valid : invalid) += 1;
    }
  }
  std::printf("valid %d, invalid %d\n", valid, invalid);
  EXPECT_GT(invalid, 50);  // the near-degenerate cases do break under rounding
  EXPECT_GT(valid, 1000);
}

}  // namespace
}  // namespace mk
