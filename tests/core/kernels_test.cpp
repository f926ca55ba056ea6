// Every kernel runs the whole algorithm. Exact kernels (kernel_types.hpp: exact and the
// rational kernel over Boost's number types) must equal RationalKernel exactly on the named
// cases and on rounded near-degenerate pairs (the exact transforms are tests/oracle's
// differential test); kernels with exact predicates must be exact where nothing is rounded;
// rounded crossings' differences are recorded, never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "canonical.hpp"
#include "generators.hpp"
#include "kernel_types.hpp"

namespace mk::test {
namespace {

constexpr Operation kOps[] = {Operation::intersection, Operation::union_, Operation::difference,
                              Operation::symmetric_difference};

template <class K>
class ExactKernels : public ::testing::Test {};
TYPED_TEST_SUITE(ExactKernels, ExactKernelTypes, KernelName);

TYPED_TEST(ExactKernels, NamedCasesExactly) {
  using K = TypeParam;
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      const auto r = boolean_op<K>(nc.a, nc.b, Options{e.op, e.regular, EfOrganisation::hash, PairSearch::sweep});
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

TYPED_TEST(ExactKernels, AgreesWithRationalOnRoundedNearDegeneratePairs) {
  using K = TypeParam;
  const std::uint64_t seed = 424242;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int runs = 0;
  // Boost's header-only rationals cost several times GMP's: fewer pairs for them.
  const int pairs = K::name == RationalCppKernel::name ? 200 : 400;
  for (int iter = 0; iter < pairs; ++iter) {
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
          EXPECT_THROW(boolean_op<K>(a, b, opt), InvalidInput);
          continue;
        }
        const auto fast = boolean_op<K>(a, b, opt);
        ASSERT_EQ(show(canonical(fast)), show(canonical(exact)))
            << "iter " << iter << " " << operation_name(op) << " regular " << regular << "\nA " << describe(a)
            << "\nB " << describe(b);
        ASSERT_EQ(fast.unbounded, exact.unbounded);
        ++runs;
      }
    }
  }
  std::cout << K::name << ": " << runs << " runs agree exactly\n";
  EXPECT_GT(runs, pairs * 6);
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

template <class K>
class RoundedKernels : public ::testing::Test {};
TYPED_TEST_SUITE(RoundedKernels, RoundedKernelTypes, KernelName);

template <class K>
class ExactPredicateKernels : public ::testing::Test {};
#ifdef MK_WITH_CGAL
using ExactPredicateKernelTypes = ::testing::Types<IntervalKernel, AdaptiveKernel, CgalKernel>;
#else
using ExactPredicateKernelTypes = ::testing::Types<IntervalKernel, AdaptiveKernel>;
#endif
TYPED_TEST_SUITE(ExactPredicateKernels, ExactPredicateKernelTypes, KernelName);

TYPED_TEST(ExactPredicateKernels, ExpectedPolygonsWhereNothingIsRounded) { expect_exact_without_crossings<TypeParam>(); }

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

TYPED_TEST(RoundedKernels, OverflowingCrossingPointsAreReportedNotWritten) { expect_overflow_reported<TypeParam>(); }

TYPED_TEST(ExactKernels, CrossingPointsNearOverflowAreExact) {
  using K = TypeParam;
  const Polygon a{{{{-1e300, -1e300}, {1e300, -1e300}, {1e300, 1e300}, {-1e300, 1e300}}}, PolygonType::island};
  const Polygon b{{{{0, -1.5e300}, {1.5e300, 0}, {0, 1.5e300}, {-1.5e300, 0}}}, PolygonType::island};
  const auto e = canonical(boolean_op<K>(a, b, Options{Operation::intersection}));
  const auto q = canonical(boolean_op<RationalKernel>(a, b, Options{Operation::intersection}));
  EXPECT_EQ(show(e), show(q));
  // An octagon: four corners of B cut off by A's sides.
  const auto r = boolean_op<K>(a, b, Options{Operation::intersection});
  ASSERT_EQ(r.cycles.size(), 1u);
  EXPECT_EQ(r.cycles[0].vertices.size(), 8u);
  EXPECT_EQ(r.stats.crossings, 8u);
}

}  // namespace
}  // namespace mk::test
