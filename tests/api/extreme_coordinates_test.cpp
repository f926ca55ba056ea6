// mk::compute on coordinates at the ends of the double range (issue 10, item 1): no trap, no
// NaN, an area beyond the largest double is +inf with area_beyond_double set and the exact
// area still exact; subnormal coordinates give exact results and areas rounded to nearest.
// [MK89 §3.2] (polygonoperation) [IEEE754 §4.3.1] (round to nearest, overflow to infinity)
// Preconditions: none.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/mkbool.hpp"

namespace mk {
namespace {

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return Polygon{{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}, PolygonType::island};
}

// The exact area of an axis-parallel rectangle of doubles, as "p/q" or "p".
std::string exact_rectangle_area(double x0, double y0, double x1, double y1) {
  const mpq_class a = (mpq_class(x1) - mpq_class(x0)) * (mpq_class(y1) - mpq_class(y0));
  return a.get_str();
}

constexpr Operation all_operations[] = {Operation::intersection, Operation::union_, Operation::difference,
                                        Operation::symmetric_difference};

TEST(apiExtremeCoordinates, AreaBeyondTheLargestDoubleIsInfiniteAndFlagged) {
  // The reproducer of issue 10: a result area of 1e400 killed the caller with SIGFPE.
  const Polygon a = rectangle(0, 0, 1e200, 1e200);
  for (const auto kernel : kernel_names()) {
    SCOPED_TRACE(std::string(kernel));
    BooleanOptions o;
    o.area_exact = true;  // asked for: off by default
    o.kernel = std::string(kernel);
    const BooleanOutput r = compute(a, a, o);
    ASSERT_TRUE(r.stats.area.has_value());
    EXPECT_TRUE(std::isinf(*r.stats.area) && *r.stats.area > 0) << *r.stats.area;
    EXPECT_TRUE(r.stats.area_beyond_double);
    if (is_exact_kernel(kernel)) {
      ASSERT_TRUE(r.stats.area_exact.has_value());
      EXPECT_EQ(*r.stats.area_exact, exact_rectangle_area(0, 0, 1e200, 1e200));
    }
  }
}

TEST(apiExtremeCoordinates, AreaAtTheLargestDoubleIsFiniteAndJustAboveIsNot) {
  // 2^1023 x 1.5 is below DBL_MAX; 2^1023 x 2 = 2^1024 is beyond it.
  const double x = std::ldexp(1.0, 1023);
  for (const auto kernel : kernel_names()) {
    SCOPED_TRACE(std::string(kernel));
    BooleanOptions o;
    o.area_exact = true;  // asked for: off by default
    o.kernel = std::string(kernel);
    const BooleanOutput fits = compute(rectangle(0, 0, x, 1.5), rectangle(0, 0, x, 1.5), o);
    ASSERT_TRUE(fits.stats.area.has_value());
    EXPECT_EQ(*fits.stats.area, 1.5 * x);
    EXPECT_FALSE(fits.stats.area_beyond_double);
    const BooleanOutput beyond = compute(rectangle(0, 0, x, 2), rectangle(0, 0, x, 2), o);
    ASSERT_TRUE(beyond.stats.area.has_value());
    EXPECT_EQ(*beyond.stats.area, HUGE_VAL);
    EXPECT_TRUE(beyond.stats.area_beyond_double);
  }
}

TEST(apiExtremeCoordinates, EveryOperationAtTheEndsOfTheRangeIsExact) {
  const double m = DBL_MAX;
  const double s = std::numeric_limits<double>::denorm_min();
  const Polygon square = rectangle(-m, -m, m, m);
  const Polygon diamond{{{{-m, 0}, {0, -m}, {m, 0}, {0, m}}}, PolygonType::island};
  const Polygon thin = rectangle(0, 0, m, s);  // the area of a subnormal times DBL_MAX
  const Polygon tiny = rectangle(0, 0, 3 * s, 2 * s);
  const Polygon tiny_b = rectangle(s, s, 4 * s, 3 * s);
  struct Pair {
    const Polygon* a;
    const Polygon* b;
  };
  for (const Pair& p : {Pair{&square, &diamond}, Pair{&thin, &square}, Pair{&tiny, &tiny_b}, Pair{&thin, &tiny}}) {
    for (const Operation op : all_operations) {
      for (const bool regular : {true, false}) {
        SCOPED_TRACE(std::string(operation_name(op)) + (regular ? " regular" : " non-regular"));
        BooleanOptions o;
        o.area_exact = true;  // asked for: off by default
        o.op = op;
        o.regular = regular;
        o.kernel = "exact";
        const BooleanOutput exact = compute(*p.a, *p.b, o);
        o.kernel = "rational";
        const BooleanOutput rational = compute(*p.a, *p.b, o);
        ASSERT_TRUE(exact.stats.area_exact.has_value());
        EXPECT_EQ(exact.stats.area_exact, rational.stats.area_exact);
        ASSERT_TRUE(exact.stats.area.has_value());
        EXPECT_FALSE(std::isnan(*exact.stats.area));
        EXPECT_EQ(exact.stats.area_beyond_double, std::isinf(*exact.stats.area));
        EXPECT_EQ(*exact.stats.area, *rational.stats.area);
        EXPECT_EQ(exact.output.rounded_valid, std::optional<bool>(true));
      }
    }
  }
}

TEST(apiExtremeCoordinates, SubnormalAreaRoundsToNearestAndStaysExact) {
  const double s = std::numeric_limits<double>::denorm_min();
  BooleanOptions o;
  o.area_exact = true;  // asked for: off by default
  const BooleanOutput r = compute(rectangle(0, 0, 3 * s, 2 * s), rectangle(0, 0, 3 * s, 2 * s), o);
  EXPECT_EQ(*r.stats.area_exact, exact_rectangle_area(0, 0, 3 * s, 2 * s));
  EXPECT_EQ(*r.stats.area, 0.0);  // 6 * 2^-2148 is far below the smallest subnormal
  EXPECT_FALSE(std::signbit(*r.stats.area));
  EXPECT_FALSE(r.stats.area_beyond_double);
  ASSERT_EQ(r.output.polygons.size(), 1u);
  EXPECT_EQ(r.output.polygons[0].shell.size(), 4u);
}

TEST(apiExtremeCoordinates, RoundedKernelsNeverGiveNaNAreas) {
  // Shoelace products of coordinates near DBL_MAX overflow; inf - inf would be NaN.
  const double m = DBL_MAX;
  const Polygon square = rectangle(-m, -m, m, m);
  const Polygon diamond{{{{-m, 0}, {0, -m}, {m, 0}, {0, m}}}, PolygonType::island};
  for (const auto kernel : kernel_names()) {
    SCOPED_TRACE(std::string(kernel));
    BooleanOptions o;
    o.area_exact = true;  // asked for: off by default
    o.kernel = std::string(kernel);
    o.op = Operation::symmetric_difference;
    try {
      const BooleanOutput r = compute(square, diamond, o);
      ASSERT_TRUE(r.stats.area.has_value());
      EXPECT_FALSE(std::isnan(*r.stats.area));
      EXPECT_EQ(r.stats.area_beyond_double, std::isinf(*r.stats.area));
    } catch (const KernelFailure&) {
      EXPECT_FALSE(is_exact_kernel(kernel));  // the double kernel's failures are data
    }
  }
}

TEST(apiExtremeCoordinates, InconsistentPredicatesNearTheLargestDoublesNeverCrash) {
  // A lattice polygon of 14 points times 1e301 (the harness's generator `magnitude`), with
  // itself and a copy moved along an edge: the naive kernel's products overflow and its
  // predicates answer inconsistently, and sorting edges by them ran past the range (SIGSEGV
  // in the point locator's sweep, 2026-11-28). Every kernel now answers or throws; the exact
  // ones answer exactly.
  const std::vector<std::pair<double, double>> lattice = {{-37, -43}, {-32, -41}, {-28, -42}, {-21, -36}, {-19, -34},
                                                         {-17, -22}, {-24, -23}, {-28, -25}, {-27, -18}, {-36, -17},
                                                         {-35, -26}, {-36, -26}, {-38, -25}, {-35, -30}};
  Polygon a, b;
  a.rings.emplace_back();
  b.rings.emplace_back();
  for (const auto& [x, y] : lattice) {
    a.rings[0].push_back({x * 1e301, y * 1e301});
    b.rings[0].push_back({(x + 5) * 1e301, (y + 4) * 1e301});
  }
  int answered = 0, refused = 0;
  for (const auto kernel : kernel_names()) {
    for (const Polygon* other : {&a, &b}) {
      for (const Operation op : all_operations) {
        SCOPED_TRACE(std::string(kernel) + " " + std::string(operation_name(op)));
        BooleanOptions o;
        o.kernel = std::string(kernel);
        o.op = op;
        o.area_exact = true;
        try {
          const BooleanOutput r = compute(a, *other, o);
          ++answered;
          if (is_exact_kernel(kernel) && other == &a) {
            // A op A: A itself (intersection, union) or nothing.
            const bool whole = op == Operation::intersection || op == Operation::union_;
            BooleanOptions alone = o;
            alone.op = Operation::union_;
            const BooleanOutput self = compute(a, Polygon{}, alone);
            EXPECT_EQ(*r.stats.area_exact, whole ? *self.stats.area_exact : std::string("0"));
          }
        } catch (const KernelFailure&) {
          ++refused;
          EXPECT_FALSE(is_exact_kernel(kernel));
        }
      }
    }
  }
  EXPECT_GT(answered, 0);
  std::printf("near 1e301: %d answered, %d refused by inexact kernels\n", answered, refused);
}

}  // namespace
}  // namespace mk
