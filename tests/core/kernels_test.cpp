// Every kernel runs the whole algorithm. Exact kernels must equal RationalKernel exactly on
// the named cases and on rounded near-degenerate pairs (the exact transforms are
// tests/oracle's differential test); kernels with exact predicates must be exact where
// nothing is rounded; rounded crossings' differences are recorded, never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/filtered_kernels.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#ifdef MK_WITH_CGAL
#include "arithmetic/kernels/cgal_kernel.hpp"
#endif
#include "canonical.hpp"
#include "generators.hpp"

namespace mk::test {
namespace {

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

TEST(ExactKernel, NamedCasesExactly) {
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      const auto r = boolean_op<ExactKernel>(nc.a, nc.b, Options{e.op, e.regular, EfOrganisation::hash, PairSearch::sweep});
      EXPECT_EQ(show(canonical(r)), show(canonical(e.cycles))) << nc.name << " " << operation_name(e.op);
      EXPECT_EQ(r.unbounded, e.unbounded) << nc.name;
    }
  }
}

// Near-degenerate inputs for the filters: the grid polygons scaled by a factor that is not
// a power of two and moved off the origin, then rounded to doubles, so that collinearities
// become near-collinearities (exact transforms that keep every degeneracy are the families
// of tests/oracle). Each offset's ulp is far below the scaled grid step, so no shape
// collapses onto a coarser lattice (checked: every ring keeps its distinct points).
struct Rounded {
  double factor;
  double offset;
};
constexpr Rounded kRoundings[] = {{0.1, 0.3}, {1.0 / 3.0, 1e6}, {0.7, 1099511627776.5} /* 2^40 + 1/2 */, {1e-5, 1e3}};

Polygon scaled(Polygon p, const Rounded& s) {
  for (auto& r : p.rings) {
    for (auto& v : r) v = {v.x * s.factor + s.offset, v.y * s.factor + s.offset};
  }
  return p;
}

std::size_t distinct_points(const Ring& r) {
  std::vector<std::pair<double, double>> v;
  for (const auto& p : r) v.push_back({p.x, p.y});
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

TEST(ExactKernel, AgreesWithRationalOnRoundedNearDegeneratePairs) {
  const std::uint64_t seed = 424242;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int runs = 0;
  for (int iter = 0; iter < 400; ++iter) {
    const Rounded& s = kRoundings[iter % std::size(kRoundings)];
    const Polygon ga = random_polygon(rng, true);
    const Polygon gb = random_polygon(rng, true);
    const Polygon a = scaled(ga, s), b = scaled(gb, s);
    for (std::size_t i = 0; i < a.rings.size(); ++i) ASSERT_EQ(distinct_points(a.rings[i]), distinct_points(ga.rings[i]));
    for (std::size_t i = 0; i < b.rings.size(); ++i) ASSERT_EQ(distinct_points(b.rings[i]), distinct_points(gb.rings[i]));
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        const Options opt{op, regular, EfOrganisation::hash, PairSearch::sweep};
        BooleanResult<RationalKernel> exact;
        try {
          exact = boolean_op<RationalKernel>(a, b, opt);
        } catch (const InvalidInput&) {
          // Rounding can make a ring cross itself: then both kernels must reject it.
          EXPECT_THROW(boolean_op<ExactKernel>(a, b, opt), InvalidInput);
          continue;
        }
        const auto fast = boolean_op<ExactKernel>(a, b, opt);
        ASSERT_EQ(show(canonical(fast)), show(canonical(exact)))
            << "iter " << iter << " " << operation_name(op) << " regular " << regular << "\nA " << describe(a)
            << "\nB " << describe(b);
        ASSERT_EQ(fast.unbounded, exact.unbounded);
        ++runs;
      }
    }
  }
  std::cout << runs << " runs agree exactly\n";
  EXPECT_GT(runs, 2500);
}

// Kernels with exact predicates and rounded crossing points (interval, adaptive, cgal): on
// a named case without crossings nothing is rounded, so the result must be the expected
// one exactly; where there are crossings, their differences are recorded, not asserted.
template <class K>
void expect_exact_without_crossings() {
  int asserted = 0, recorded = 0;
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      const auto r = boolean_op<K>(nc.a, nc.b, Options{e.op, e.regular, EfOrganisation::hash, PairSearch::sweep});
      if (r.stats.crossings == 0) {
        EXPECT_EQ(show(canonical(r)), show(canonical(e.cycles))) << K::name << " " << nc.name << " " << operation_name(e.op);
        ++asserted;
      } else if (show(canonical(r)) != show(canonical(e.cycles))) {
        ++recorded;
        std::cout << K::name << " differs on " << nc.name << " " << operation_name(e.op) << " (rounded crossings)\n";
      }
    }
  }
  std::cout << K::name << ": " << asserted << " expectations without crossings met exactly, " << recorded
            << " with crossings differing\n";
  EXPECT_GT(asserted, 20);
}

TEST(RoundedKernels, ExactPredicatesGiveTheExpectedPolygonsWhereNothingIsRounded) {
  expect_exact_without_crossings<IntervalKernel>();
  expect_exact_without_crossings<AdaptiveKernel>();
#ifdef MK_WITH_CGAL
  expect_exact_without_crossings<CgalKernel>();
#endif
}

// Squares of side 2e300 crossing each other: the rounded construction of their crossing
// points overflows (products of 1e300-sized differences). Kernels that round must report
// that as an error instead of writing NaN or infinite coordinates; exact kernels are
// unaffected.
template <Kernel K>
void expect_overflow_reported() {
  const Polygon a{{{{-1e300, -1e300}, {1e300, -1e300}, {1e300, 1e300}, {-1e300, 1e300}}}, PolygonType::island};
  const Polygon b{{{{0, -1.5e300}, {1.5e300, 0}, {0, 1.5e300}, {-1.5e300, 0}}}, PolygonType::island};
  try {
    const auto r = boolean_op<K>(a, b, Options{Operation::intersection});
    // A kernel whose arithmetic happens not to overflow here must still be finite.
    for (const auto& c : r.cycles) {
      for (const int v : c.vertices) {
        const Point p = K::approx(r.vertex(v));
        EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << K::name;
      }
    }
    ADD_FAILURE() << K::name << ": expected the overflow to be reported";
  } catch (const KernelFailure& e) {
    // Plain double predicates overflow too and fail earlier, with their own message.
    if (K::name != DoubleKernel::name) {
      EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
    }
  }
}

TEST(RoundedKernels, OverflowingCrossingPointsAreReportedNotWritten) {
  expect_overflow_reported<DoubleKernel>();
  expect_overflow_reported<IntervalKernel>();
  expect_overflow_reported<AdaptiveKernel>();
#ifdef MK_WITH_CGAL
  expect_overflow_reported<CgalKernel>();
#endif
}

TEST(ExactKernel, CrossingPointsNearOverflowAreExact) {
  const Polygon a{{{{-1e300, -1e300}, {1e300, -1e300}, {1e300, 1e300}, {-1e300, 1e300}}}, PolygonType::island};
  const Polygon b{{{{0, -1.5e300}, {1.5e300, 0}, {0, 1.5e300}, {-1.5e300, 0}}}, PolygonType::island};
  const auto e = canonical(boolean_op<ExactKernel>(a, b, Options{Operation::intersection}));
  const auto q = canonical(boolean_op<RationalKernel>(a, b, Options{Operation::intersection}));
  EXPECT_EQ(show(e), show(q));
  // An octagon: four corners of B cut off by A's sides.
  const auto r = boolean_op<ExactKernel>(a, b, Options{Operation::intersection});
  ASSERT_EQ(r.cycles.size(), 1u);
  EXPECT_EQ(r.cycles[0].vertices.size(), 8u);
  EXPECT_EQ(r.stats.crossings, 8u);
}

}  // namespace
}  // namespace mk::test
