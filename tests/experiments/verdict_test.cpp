// Tests of the verdict logic: exact_match up to the start vertex, valid_different with its
// exact symmetric-difference area, invalid_output for crossing or misoriented rings; the
// CSV schema and the regression case format. [MK89 §3.3]
// Preconditions: MK_SOURCE_DIR is the repository (the schema test reads experiments/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "api/mkbool.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/results.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {
namespace {

Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// The reference's output without its exact coordinates: what an inexact kernel reports.
Output rounded(Output o) {
  for (auto& c : o.irreducible) c.exact.clear();
  o.rounded_valid.reset();
  return o;
}

const Polygon kA{{box(0, 0, 2, 2)}, PolygonType::island};
const Polygon kB{{box(1, 1, 3, 3)}, PolygonType::island};

TEST(Verdict, ReferenceAgainstItselfIsExactMatch) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  EXPECT_EQ(assess(ref.output, ref).verdict, Verdict::exact_match);
  EXPECT_EQ(assess(rounded(ref.output), ref).verdict, Verdict::exact_match);
}

TEST(Verdict, AnotherStartVertexIsStillExactMatch) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  Output o = rounded(ref.output);
  ASSERT_EQ(o.irreducible.size(), 1u);
  auto& v = o.irreducible[0].vertices;
  std::rotate(v.begin(), v.begin() + 2, v.end());
  EXPECT_EQ(assess(o, ref).verdict, Verdict::exact_match);
}

TEST(Verdict, EveryKernelMatchesOnIntegerCrossings) {
  const ExactResult ref = exact_reference(kA, kB, Operation::union_, true, true);
  for (const auto k : kernel_names()) {
    BooleanOptions options{Operation::union_, true, std::string(k)};
    options.exact_coordinates = true;
    const BooleanOutput out = compute(kA, kB, options);
    EXPECT_EQ(assess(out.output, ref).verdict, Verdict::exact_match) << k;
  }
}

TEST(Verdict, VertexMovedOneUlpIsValidDifferentWithExactArea) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  Output o = rounded(ref.output);
  bool moved = false;
  for (auto& p : o.irreducible[0].vertices) {
    if (p == Point{2, 2}) {
      p.x = std::nextafter(2.0, 3.0);  // the square (1,1)-(2,2) gains a triangle of area ulp(2)/2
      moved = true;
    }
  }
  ASSERT_TRUE(moved);
  const Assessment a = assess(o, ref);
  EXPECT_EQ(a.verdict, Verdict::valid_different);
  ASSERT_TRUE(a.symdiff_area.has_value());
  EXPECT_EQ(*a.symdiff_area, std::ldexp(1.0, -52));
  EXPECT_EQ(*a.area_error, std::ldexp(1.0, -52));  // exact area is 1
}

TEST(Verdict, CrossingEdgesAreInvalidOutput) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  Output o = rounded(ref.output);
  o.irreducible[0].vertices = {{1, 1}, {2, 2}, {2, 1}, {1, 2}};  // a bow tie
  std::string why;
  EXPECT_FALSE(is_valid_output(o, PolygonType::island, &why));
  EXPECT_EQ(assess(o, ref).verdict, Verdict::invalid_output);
}

TEST(Verdict, OrientationAgainstTypeIsInvalidOutput) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  Output o = rounded(ref.output);
  std::reverse(o.irreducible[0].vertices.begin(), o.irreducible[0].vertices.end());
  const Assessment a = assess(o, ref);
  EXPECT_EQ(a.verdict, Verdict::invalid_output);
  EXPECT_NE(a.note.find("orientation"), std::string::npos);
}

TEST(Verdict, RegionsOverlappingAtSharedVerticesAreInvalid) {
  Output o;
  // Two islands meeting at a corner: valid.
  o.irreducible = {{box(0, 0, 1, 1), {}, PolygonType::island}, {box(1, 1, 2, 2), {}, PolygonType::island}};
  EXPECT_TRUE(is_valid_output(o, PolygonType::island));
  // An island with a hole touching it at a corner: valid.
  o.irreducible = {{box(0, 0, 4, 4), {}, PolygonType::island}, {{{0, 0}, {1, 2}, {2, 1}}, {}, PolygonType::hole}};
  EXPECT_TRUE(is_valid_output(o, PolygonType::island));
  // Two islands sharing two vertices, one's edge a chord inside the other: no edges cross,
  // but the regions overlap.
  o.irreducible = {{box(0, 0, 4, 4), {}, PolygonType::island}, {{{0, 0}, {4, 4}, {-1, 5}}, {}, PolygonType::island}};
  std::string why;
  EXPECT_FALSE(is_valid_output(o, PolygonType::island, &why));
  EXPECT_NE(why.find("overlap at a shared vertex"), std::string::npos) << why;
}

TEST(Verdict, MissingPolygonIsValidDifferentByItsArea) {
  const Polygon b{{box(5, 0, 7, 2)}, PolygonType::island};
  const ExactResult ref = exact_reference(kA, b, Operation::union_, true, true);
  Output o = rounded(ref.output);
  ASSERT_EQ(o.irreducible.size(), 2u);
  o.irreducible.pop_back();
  const Assessment a = assess(o, ref);
  EXPECT_EQ(a.verdict, Verdict::valid_different);
  EXPECT_EQ(*a.symdiff_area, 4);
  EXPECT_EQ(*a.area_error, 0.5);
}

TEST(Verdict, UnboundedInsteadOfBoundedHasInfiniteAreaError) {
  const ExactResult ref = exact_reference(kA, kB, Operation::intersection, true, true);
  Output o = rounded(ref.output);
  o.unbounded = true;
  o.irreducible[0].type = PolygonType::hole;
  std::reverse(o.irreducible[0].vertices.begin(), o.irreducible[0].vertices.end());
  const Assessment a = assess(o, ref);
  EXPECT_EQ(a.verdict, Verdict::valid_different);
  EXPECT_TRUE(std::isinf(*a.area_error));
}

TEST(Verdict, ExactKernelsAreComparedByTheirExactCoordinates) {
  // B's edge y = 3x crosses A's edge y = 1 at x = 1/3, not a double.
  const Polygon a{{box(-1, 1, 2, 2)}, PolygonType::island};
  const Polygon b{{{{0, 0}, {1, 3}, {-2, 3}}}, PolygonType::island};
  const ExactResult ref = exact_reference(a, b, Operation::intersection, true, true);
  Output o = ref.output;
  bool changed = false;
  for (auto& c : o.irreducible) {
    for (auto& s : c.exact) {
      if (s == "1/3") {
        s = "333333333333333333333333333/1000000000000000000000000000";  // rounds the same
        changed = true;
      }
    }
  }
  ASSERT_TRUE(changed);
  EXPECT_EQ(assess(rounded(o), ref).verdict, Verdict::exact_match);  // equal once rounded
  const Assessment x = assess(o, ref);
  EXPECT_EQ(x.verdict, Verdict::valid_different);
  EXPECT_GT(*x.symdiff_area, 0);
}

TEST(Verdict, SymmetricDifferenceAndParityAreas) {
  const auto cycles = [](const Polygon& p) {
    std::vector<ExactCycle> out;
    for (const auto& r : p.rings) {
      ExactCycle c;
      for (const auto& v : r) c.vertices.push_back(RationalKernel::point(v));
      out.push_back(c);
    }
    return out;
  };
  const auto sd = symmetric_difference_area(cycles(kA), false, cycles(kB), false);
  ASSERT_TRUE(sd.has_value());
  EXPECT_FALSE(sd->infinite);
  EXPECT_EQ(sd->area, 6);
  EXPECT_EQ(sd->consistent, true);
  const Polygon with_hole{{box(0, 0, 4, 4), box(1, 1, 2, 2)}, PolygonType::island};
  std::vector<std::vector<RationalPoint>> rings;
  for (const auto& c : cycles(with_hole)) rings.push_back(c.vertices);
  EXPECT_EQ(parity_area(rings), 15);
  EXPECT_FALSE(violated_identity(with_hole, kB).has_value());
  EXPECT_TRUE(symmetric_difference_area(cycles(kA), true, cycles(kB), false)->infinite);
}

TEST(Results, CsvRowsRoundTrip) {
  ResultRow r;
  r.case_index = 7;
  r.generator = "ulp_perturbed";
  r.variant = "outside_triangle";
  r.params = "k=-3";
  r.seed = 123456789012345ULL;
  r.size = 7;
  r.op = "xor";
  r.regular = false;
  r.kernel = "double";
  r.verdict = Verdict::valid_different;
  r.area_error = 1.5e-16;
  r.symdiff_area = std::ldexp(1.0, -60);
  r.op_ns = 12345;
  r.message = "a \"quoted\", comma\nand newline";
  const ResultRow b = parse_csv_row(to_csv(r));
  EXPECT_EQ(b.case_index, r.case_index);
  EXPECT_EQ(b.params, r.params);
  EXPECT_EQ(b.seed, r.seed);
  EXPECT_EQ(b.regular, false);
  EXPECT_EQ(b.verdict, r.verdict);
  EXPECT_EQ(b.area_error, r.area_error);
  EXPECT_EQ(b.symdiff_area, r.symdiff_area);
  EXPECT_FALSE(b.exact_area.has_value());
  EXPECT_EQ(b.message, "a \"quoted\", comma and newline");
}

TEST(Results, TheSchemaIsDocumented) {
  std::ifstream in(std::string(MK_SOURCE_DIR) + "/experiments/README.md");
  ASSERT_TRUE(in) << "experiments/README.md";
  const std::string doc((std::istreambuf_iterator<char>(in)), {});
  for (const auto c : csv_columns()) {
    EXPECT_NE(doc.find("| `" + std::string(c) + "` |"), std::string::npos) << "column " << c << " not in the schema table";
  }
  // The name quoted, built by appending (GCC 12's -Wrestrict misreads "`" + string&& once
  // inlined: its bug 105329).
  const auto quoted = [](Verdict v) { return std::string("`").append(verdict_name(v)).append("`"); };
  for (const Verdict v : all_verdicts) {
    EXPECT_NE(doc.find(quoted(v)), std::string::npos) << verdict_name(v);
  }
  for (const Verdict v : peer_verdicts) {
    EXPECT_NE(doc.find(quoted(v)), std::string::npos) << verdict_name(v);
  }
}

TEST(Artefacts, RegressionCasesRoundTrip) {
  const Polygon with_hole{{box(0, 0, 4, 4), box(1, 1, 2, 2), box(5, 0, 6, 0.1)}, PolygonType::island};
  const Polygon hole_type{{box(0, 0, 1, 1)}, PolygonType::hole};
  const Polygon two_sided{{{{0, 0}, {0.1, 0.30000000000000004}}}, PolygonType::island};
  for (const auto& [a, b] : {std::pair{with_hole, hole_type}, std::pair{hole_type, two_sided}}) {
    const std::string text = regression_case_text(a, b, Operation::difference, false, {"note"});
    std::istringstream lines(text);
    std::string first;
    std::getline(lines, first);
    // WKT for the island (MULTIPOLYGON: two shells), native JSON for hole-type polygons.
    EXPECT_EQ(first.rfind(a.type == PolygonType::island ? "MULTIPOLYGON" : "{", 0), 0u) << first;
    const RegressionCase c = read_regression_case(text);
    EXPECT_EQ(c.op, Operation::difference);
    EXPECT_FALSE(c.regular);
    for (const auto& [x, y] : {std::pair{&a, &c.a}, std::pair{&b, &c.b}}) {
      EXPECT_EQ(x->type, y->type);
      ASSERT_EQ(x->rings.size(), y->rings.size());
      for (std::size_t i = 0; i < x->rings.size(); ++i) EXPECT_EQ(x->rings[i], y->rings[i]);
    }
  }
}

}  // namespace
}  // namespace mk::experiments
