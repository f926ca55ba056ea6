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

namespace mk {
namespace {

// Full check: the general function over the rounded rings (sort, sweep).
bool full_check(const std::vector<std::vector<Point>>& rounded) { return is_valid_rounded_output<ExactKernel>(rounded); }

std::vector<std::vector<Point>> round_result(const BooleanResult<ExactKernel>& r) {
  std::vector<std::vector<Point>> out;
  for (const auto& c : r.cycles) {
    out.emplace_back();
    for (const int id : c.vertices) out.back().push_back(ExactKernel::approx(r.vertex(id)));
  }
  return out;
}

// Triangles of nearly collinear points a few ulps apart (whose crossings often round onto
// each other's edges) and plain random triangles.
Polygon random_triangle(std::mt19937_64& rng, bool near_degenerate) {
  std::uniform_real_distribution<double> u(-1, 1);
  Polygon p;
  if (!near_degenerate) {
    p.rings.push_back({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}});
    return p;
  }
  const double x0 = u(rng), y0 = u(rng);
  const double dx = u(rng), dy = u(rng);
  const auto ulps = [&](double v) { return std::nextafter(v, v + static_cast<double>(rng() % 7) - 3); };
  p.rings.push_back({{x0, y0}, {ulps(x0 + dx), ulps(y0 + dy)}, {x0 + 0.5 * dx + 1e-15 * u(rng), y0 + 0.5 * dy}});
  return p;
}

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
