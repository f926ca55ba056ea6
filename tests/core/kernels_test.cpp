// Every kernel runs the whole algorithm. Exact kernels (kernel_types.hpp: exact and the
// rational kernel over Boost's number types) must equal RationalKernel exactly on the named
// cases and on thousands of generated degenerate pairs (differential test); the
// rounded-construction kernels' disagreements are recorded as findings, never asserted.
#include <gtest/gtest.h>

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

// The grid polygons scaled by a factor that is not a power of two: coordinates stop being
// representable exactly, so collinearities become near-collinearities for the filters.
Polygon scaled(Polygon p, double f, double dx) {
  for (auto& r : p.rings) {
    for (auto& v : r) v = {v.x * f + dx, v.y * f + dx};
  }
  return p;
}

TYPED_TEST(ExactKernels, AgreesWithRationalOnGeneratedDegeneratePairs) {
  using K = TypeParam;
  const std::uint64_t seed = 424242;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  int runs = 0;
  // Boost's header-only rationals cost several times GMP's: fewer pairs for them.
  const int pairs = K::name == RationalCppKernel::name ? 300 : 600;
  for (int iter = 0; iter < pairs; ++iter) {
    Polygon a = random_polygon(rng, true);
    Polygon b = random_polygon(rng, true);
    if (iter % 3 == 1) {
      a = scaled(a, 0.1, 0.3);
      b = scaled(b, 0.1, 0.3);
    } else if (iter % 3 == 2) {
      a = scaled(a, 1e-7, 1e10);
      b = scaled(b, 1e-7, 1e10);
    }
    for (const Operation op : kOps) {
      for (const bool regular : {true, false}) {
        const Options opt{op, regular, EfOrganisation::hash, PairSearch::sweep};
        const auto exact = boolean_op<RationalKernel>(a, b, opt);
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
}

template <class K>
void record_named_cases() {
  int agree = 0, differ = 0, failed = 0, total = 0;
  for (const auto& nc : named_cases()) {
    for (const auto& e : nc.expect) {
      ++total;
      try {
        const auto r = boolean_op<K>(nc.a, nc.b, Options{e.op, e.regular, EfOrganisation::hash, PairSearch::sweep});
        if (show(canonical(r)) == show(canonical(e.cycles))) {
          ++agree;
        } else {
          ++differ;
          std::cout << K::name << " differs on " << nc.name << " " << operation_name(e.op) << "\n";
        }
      } catch (const KernelFailure& ex) {
        ++failed;
        std::cout << K::name << " failed on " << nc.name << ": " << ex.what() << "\n";
      }
    }
  }
  std::cout << K::name << " on named cases: " << agree << " agree, " << differ << " differ, " << failed
            << " kernel failures\n";
  EXPECT_EQ(agree + differ + failed, total);
}

template <class K>
class RoundedKernels : public ::testing::Test {};
TYPED_TEST_SUITE(RoundedKernels, RoundedKernelTypes, KernelName);

TYPED_TEST(RoundedKernels, NamedCasesRecorded) { record_named_cases<TypeParam>(); }

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
