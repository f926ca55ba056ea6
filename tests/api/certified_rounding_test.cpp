// Certified rounding through mk::compute: with default options the written polygons are
// valid (exact OGC check, and GEOS's isValid when built with GEOS) on near-degenerate
// triangle pairs where the nearest doubles are often invalid; --rounding nearest keeps
// them and says so; a user grid puts every vertex on it. [Ho99] [HP02] [BRIEF §6a]
// Preconditions: none. MK_ROUNDING_PAIRS overrides the number of pairs (default 250 per
// variant); the counts are printed with the seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "api/mkbool.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/ogc_validity.hpp"
#include "tests/api/near_degenerate.hpp"
#ifdef MK_HAVE_GEOS
#include "tests/api/geos_validity.hpp"
#endif

namespace mk {
namespace {


int pairs_per_variant() {
  const char* env = std::getenv("MK_ROUNDING_PAIRS");
  return env ? std::atoi(env) : 250;
}

struct Counts {
  int runs = 0, nearest_invalid = 0, snapped = 0, invalid = 0, geos_invalid = 0, geos_unscaled_invalid = 0;
  int merged = 0;  // outputs written with the nearest doubles in which two vertices of a cycle rounded to one
};

// Whether a ring repeats a point, consecutively or around its end.
bool repeats_a_point(const Ring& r) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i] == r[(i + 1) % r.size()]) return true;
  }
  return false;
}

// Every operation on every pair: the written polygons must be valid.
Counts run_family(std::uint64_t seed, int variant, double scale, int pairs) {
  std::mt19937_64 rng(seed);
  Counts c;
#ifdef MK_HAVE_GEOS
  test::Geos geos;
#endif
  for (int i = 0; i < pairs; ++i) {
    const auto pair = test::near_degenerate_pair(rng, variant, scale);
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
      BooleanOptions o;
      o.op = op;
      const BooleanOutput r = compute(pair.a, pair.b, o);
      ++c.runs;
      c.nearest_invalid += !r.output.rounded_valid.value_or(false);
      c.snapped += r.output.rounding.snapped;
      const OgcValidity v = check_ogc_validity<ExactKernel>(r.output.polygons);
      // The written rings never repeat a point (the cycles' rounded vertices may).
      bool merged = false;
      for (const auto& c : r.output.irreducible) merged = merged || (c.vertices.size() >= 3 && repeats_a_point(c.vertices));
      c.merged += merged && !r.output.rounding.snapped;  // the nearest doubles written, without the repeats
      for (const auto& p : r.output.polygons) {
        EXPECT_FALSE(repeats_a_point(p.shell)) << "seed " << seed << " variant " << variant << " pair " << i;
        for (const auto& h : p.holes) EXPECT_FALSE(repeats_a_point(h)) << "seed " << seed << " variant " << variant << " pair " << i;
      }
      const bool ok = v.valid() && r.output.rounding.valid;
      c.invalid += !ok;
      EXPECT_TRUE(ok) << "seed " << seed << " variant " << variant << " pair " << i << " op " << operation_name(op);
#ifdef MK_HAVE_GEOS
      std::string why;
      c.geos_unscaled_invalid += !geos.is_valid(r.output.polygons, nullptr);
      const bool geos_ok = geos.is_valid(r.output.polygons, &why, test::unit_scale(r.output.polygons));
      c.geos_invalid += !geos_ok;
      EXPECT_TRUE(geos_ok) << "GEOS: " << why << "; seed " << seed << " variant " << variant << " pair " << i;
#endif
    }
  }
  std::printf("certified rounding, seed %llu variant %d scale %g: %d runs, nearest invalid %d, snapped %d, "
              "written invalid %d (exact check), %d (GEOS, scaled by 2^k into [1, 2)), %d (GEOS unscaled), "
              "%d with vertices merged by rounding\n",
              static_cast<unsigned long long>(seed), variant, scale, c.runs, c.nearest_invalid, c.snapped, c.invalid,
              c.geos_invalid, c.geos_unscaled_invalid, c.merged);
  return c;
}

TEST(CertifiedRounding, NearDegenerateTrianglesAreWrittenValid) {
  const int pairs = pairs_per_variant();
  int merged = 0;
  for (const int variant : {0, 1}) {
    for (const double scale : {1.0, 1e-150, 1e150}) {
      const Counts c = run_family(20261125 + static_cast<std::uint64_t>(variant), variant, scale, pairs);
      EXPECT_EQ(c.invalid, 0);
      EXPECT_EQ(c.geos_invalid, 0);
      if (pairs >= 200) {
        EXPECT_GT(c.nearest_invalid, 0) << "the family no longer breaks nearest rounding";
      }
      EXPECT_EQ(c.snapped, c.nearest_invalid);  // snapping exactly when the nearest doubles are invalid
      merged += c.merged;
    }
  }
  if (pairs >= 200) {
    EXPECT_GT(merged, 0) << "no output merged two vertices: the repeats are not tested";
  }
}

TEST(CertifiedRounding, NearestModeKeepsInvalidOutputAndSaysSo) {
  std::mt19937_64 rng(7);
  int invalid = 0;
  for (int i = 0; i < 300 && invalid == 0; ++i) {
    const auto pair = test::near_degenerate_pair(rng, 0);
    BooleanOptions o;
    o.op = Operation::intersection;
    o.rounding = RoundingMode::nearest;
    const BooleanOutput r = compute(pair.a, pair.b, o);
    EXPECT_FALSE(r.output.rounding.snapped);
    EXPECT_EQ(r.output.rounding.valid, r.output.rounded_valid.value_or(false));
    EXPECT_EQ(r.output.rounding.valid, check_ogc_validity<ExactKernel>(r.output.polygons).valid());
    invalid += !r.output.rounding.valid;
  }
  EXPECT_GT(invalid, 0);
}

TEST(CertifiedRounding, UserGridPutsEveryVertexOnIt) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 200; ++i) {
    const auto pair = test::near_degenerate_pair(rng, i % 2, 100.0);
    BooleanOptions o;
    o.op = Operation::union_;
    o.grid = "0.25";
    const BooleanOutput r = compute(pair.a, pair.b, o);
    ASSERT_TRUE(r.output.rounding.snapped);
    EXPECT_TRUE(r.output.rounding.user_grid);
    EXPECT_TRUE(r.output.rounding.valid);
    EXPECT_TRUE(check_ogc_validity<ExactKernel>(r.output.polygons).valid());
    ASSERT_TRUE(r.output.rounding.max_displacement.has_value());
    EXPECT_LE(*r.output.rounding.max_displacement, 0.7072);  // half a pixel's diagonal, in grid units
    for (const auto& p : r.output.polygons) {
      for (const auto& q : p.shell) {
        EXPECT_EQ(std::fmod(q.x, 0.25), 0.0);
        EXPECT_EQ(std::fmod(q.y, 0.25), 0.0);
      }
    }
  }
  BooleanOptions bad;
  bad.grid = "-1";
  EXPECT_THROW(compute(Polygon{}, Polygon{}, bad), std::invalid_argument);
}

TEST(CertifiedRounding, ValidNearestOutputIsLeftAlone) {
  const Polygon a{{{{0, 0}, {3, 0}, {3, 3}, {0, 3}}}};
  const Polygon b{{{{1, 1}, {4, 1}, {4, 4}, {1, 4}}}};
  BooleanOptions o;
  o.op = Operation::union_;
  const BooleanOutput r = compute(a, b, o);
  EXPECT_FALSE(r.output.rounding.snapped);
  EXPECT_TRUE(r.output.rounding.valid);
  EXPECT_EQ(r.output.polygons.size(), 1u);
}

// Found by fuzzing (fuzz_operation): A is a long two-sided ring, B a thin triangle reaching the
// subnormal range; their non-regular intersection is one dangling edge between two exact
// points that both round to (5e-324, 0), and the nearest doubles make it a zero-length edge.
// Snap rounding on the grid 2^-1074 collapses it to a point. A crossing's interval box
// reached far beyond the grid's 2^62-pixel range while the point itself did not: the
// `exact` kernel threw there (the box's bound was taken as a coordinate), `rational` did not.
// Both must write the same valid point.
TEST(CertifiedRounding, KernelsAgreeWhereACrossingsBoxLeavesTheGridRange) {
  const Polygon a{{{{3.0333174339881949e+180, 1.3980432860550687e-76}, {0, 0}}}};
  const Polygon b{{{{1.3980432860951324e-76, 1.3980432860550687e-76}, {1, 7}, {1e154, 1.7976931348623157e+308},
                    {4.9406564584124654e-324, 0}}}};
  for (const char* kernel : {"exact", "rational"}) {
    BooleanOptions o;
    o.op = Operation::intersection;
    o.regular = false;
    o.kernel = kernel;
    const BooleanOutput r = compute(a, b, o);
    EXPECT_EQ(r.output.rounding.failure, "") << kernel;
    EXPECT_TRUE(r.output.rounding.snapped) << kernel;
    EXPECT_TRUE(r.output.rounding.valid) << kernel;
    EXPECT_EQ(r.output.rounding.grid, "2^-1074") << kernel;
    ASSERT_EQ(r.output.isolated_points.size(), 1u) << kernel;
    EXPECT_TRUE(r.output.dangling_edges.empty()) << kernel;
    EXPECT_EQ(r.output.isolated_points[0].x, 0x1p-1074) << kernel;
    EXPECT_EQ(r.output.isolated_points[0].y, 0.0) << kernel;
    EXPECT_TRUE(r.output.polygons.empty()) << kernel;
  }
}

}  // namespace
}  // namespace mk
