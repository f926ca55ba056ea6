// Tests of set cases (union_all, intersection_all through the harness), of fill-rule cases
// in the sweep (every rule, regular and not) and of the fill-rule and set regression case
// files: hand-derived results, the coverage identity, a perturbed result judged wrong,
// sweeps of the fill and set generators with every exact kernel exact, and regression files
// that replay their case. [BRIEF §1, extended by issue 13]
// Preconditions: none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

#include "api/mkbool.hpp"
#include "experiments/artefacts.hpp"
#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/runner.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {
namespace {

OgcPolygon square(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// A set case built by hand: P = [0,2]^2, Q = [1,3]^2, R = [0,1] x [2,3] (its bottom edge on
// P's top edge), and P again, reversed. Union: 4 + 4 - 1 (P and Q share [1,2]^2) + 1 = 8.
// Intersection: no area; closed, P and R share the segment [0,1] x {2}, which meets Q only
// at (1, 2): one isolated point.
Case hand_set() {
  Case c;
  c.spec = {"random_set", "lattice", {{"rule", 4}}, 0};
  OgcPolygon p_again = square(0, 0, 2, 2);
  std::reverse(p_again.shell.begin(), p_again.shell.end());
  c.parts = MultiPolygon{square(0, 0, 2, 2), square(1, 1, 3, 3), square(0, 2, 1, 3), p_again};
  c.a = fill_rule_polygon(*c.parts, FillRule::union_);
  return c;
}

TEST(Sets, HandDerivedUnionAndIntersectionOfASet) {
  const Case c = hand_set();
  const ExactResult u = case_reference(c, Operation::union_, true, true);
  EXPECT_EQ(u.area, 8);
  EXPECT_FALSE(u.unbounded);
  const ExactResult i = case_reference(c, Operation::intersection, true, false);
  EXPECT_TRUE(i.cycles.empty());
  const ExactResult closed = case_reference(c, Operation::intersection, false, false);
  ASSERT_EQ(closed.cycles.size(), 1u);
  ASSERT_EQ(closed.cycles[0].vertices.size(), 1u);
  EXPECT_EQ(closed.cycles[0].vertices[0], (RationalPoint{1, 2}));
  for (const auto k : kernel_names()) {
    if (!is_exact_kernel(k)) continue;  // the rounded kernels are data, not asserted
    for (const auto& [op, regular] : {std::pair{Operation::union_, true}, std::pair{Operation::intersection, false}}) {
      BooleanOptions o{op, regular, std::string(k)};
      o.exact_coordinates = true;
      const ExactResult& ref = op == Operation::union_ ? u : closed;
      EXPECT_EQ(assess(run_operation(c, o).output, ref).verdict, Verdict::exact_match) << k;
    }
  }
  EXPECT_FALSE(runs_operation(c.spec, Operation::difference));
  EXPECT_EQ(run_operation_name(c.spec, Operation::union_), "union_all");
  EXPECT_EQ(parse_run_operation("intersection_all"), Operation::intersection);
}

// A coverage's parts share edges but never overlap: on the lattice its union's area is the
// sum of the parts' areas, computed here by the shoelace formula without the library.
TEST(Sets, CoverageGridUnionAreaIsTheSumOfItsCells) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const CaseSpec spec{"coverage_grid", "lattice", {{"n", 3 + static_cast<std::int64_t>(seed)}, {"rule", 4}}, seed};
    const Case c = make_case(spec);
    mpq_class sum = 0;
    for (const OgcPolygon& p : *c.parts) {
      std::vector<RationalPoint> ring;
      for (const Point& q : p.shell) ring.push_back(RationalKernel::point(q));
      sum += abs(twice_signed_area(ring)) / 2;
    }
    EXPECT_EQ(case_reference(c, Operation::union_, true, true).area, sum) << "seed " << seed;
  }
}

// The verdict sees a result one vertex off: the exact union of a set with one vertex moved
// is not exact_match.
TEST(Sets, APerturbedResultIsNotExact) {
  const Case c = make_case({"random_set", "rotated", {{"n", 12}, {"rule", 4}}, 5});
  BooleanOptions o{Operation::union_, true, "exact"};
  o.exact_coordinates = true;
  Output out = run_operation(c, o).output;
  const ExactResult ref = case_reference(c, Operation::union_, true, false);
  EXPECT_EQ(assess(out, ref).verdict, Verdict::exact_match);
  ASSERT_FALSE(out.irreducible.empty());
  OutputIrreducible& cycle = out.irreducible[0];
  ASSERT_GE(cycle.vertices.size(), 3u);
  cycle.vertices[0].x = std::nextafter(cycle.vertices[0].x, 1e300);
  mpq_class x(cycle.vertices[0].x);
  cycle.exact[0] = x.get_str();
  const Assessment a = assess(out, ref);
  EXPECT_NE(a.verdict, Verdict::exact_match) << a.note;
}

std::vector<std::string> fill_generator_names() {
  std::vector<std::string> out;
  for (const Generator& g : generators()) {
    if (is_fill_generator(g.name)) out.emplace_back(g.name);
  }
  return out;
}

// Fill-rule cases: each named fill generator plans every rule (param rule = 0-4) and variant,
// runs every operation regular and non-regular, every exact kernel equals the rule's exact
// reference, and the peers are left out (they do not read fill rules).
TEST(Sweep, FillGeneratorsRunEveryRuleRegularAndNot) {
  const std::vector<std::string> names = fill_generator_names();
  ASSERT_FALSE(names.empty());
  const auto plan = plan_sweep({SweepLevel::quick, 1, 11, names});
  ASSERT_EQ(plan.size(), names.size() * 2 * 5);
  std::set<std::int64_t> rules;
  for (const auto& c : plan) rules.insert(c.param("rule", -1));
  EXPECT_EQ(rules, (std::set<std::int64_t>{0, 1, 2, 3, 4}));
  RunOptions o;
  // Not the number-type variants of rational (its results, several times its cost).
  for (const auto k : kernel_names()) {
    if (!is_number_type_variant(k)) o.kernels.emplace_back(k);
  }
  const std::size_t kernels = o.kernels.size();
  for (const auto p : peer_names()) o.kernels.emplace_back(p);
  o.isolate = false;
  const auto rows = run_sweep(select_shard(plan, {}), o, "");
  EXPECT_EQ(rows.size(), plan.size() * 8 * kernels);  // 4 operations x regular or not, no peer
  std::size_t non_regular = 0;
  for (const auto& r : rows) {
    non_regular += r.regular ? 0 : 1;
    EXPECT_FALSE(is_peer(r.kernel)) << to_csv(r);
  }
  EXPECT_EQ(non_regular, rows.size() / 2);
  for (const auto& r : rows) {
    if (is_exact_kernel(r.kernel)) {
      EXPECT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
    }
  }
}

// The set generators through the sweep: union_all and intersection_all, regular or not, no
// other operation, no peer; every exact kernel equals the reference.
TEST(Sets, SweepOfTheSetGeneratorsIsExactForExactKernels) {
  std::vector<std::string> names;
  for (const Generator& g : generators()) {
    if (is_set_generator(g.name)) names.emplace_back(g.name);
  }
  ASSERT_EQ(names.size(), 3u);
  const auto plan = plan_sweep({SweepLevel::quick, 1, 13, names});
  ASSERT_EQ(plan.size(), names.size() * 2 * 2);  // one seed x 2 variants x 2 rules
  RunOptions o;
  for (const auto k : kernel_names()) {
    if (!is_number_type_variant(k)) o.kernels.emplace_back(k);
  }
  o.isolate = false;
  const auto rows = run_sweep(select_shard(plan, {}), o, "");
  EXPECT_EQ(rows.size(), plan.size() * 4 * o.kernels.size());
  std::size_t rounded_failures = 0;
  for (const auto& r : rows) {
    EXPECT_TRUE(r.op == "union_all" || r.op == "intersection_all") << to_csv(r);
    EXPECT_NE(r.kernel, "reference") << to_csv(r);
    if (is_exact_kernel(r.kernel)) {
      EXPECT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
    } else {
      rounded_failures += r.verdict == Verdict::exact_match ? 0 : 1;
    }
  }
  std::cout << "set sweep: " << rows.size() << " runs, rounded-construction kernels not exact on " << rounded_failures
            << " (base seed 13)\n";
}

// A regression case file replays its case: the set's parts (ring directions as given), the
// operation, the regularity and the fill rule come back, and the replay's exact result is
// the case's. Likewise a non-regular fill-rule case.
TEST(Sets, RegressionFilesOfSetAndFillCasesReplayTheirCase) {
  const std::vector<std::pair<CaseSpec, Operation>> cases{
      {{"nested_parts", "rotated", {{"n", 3}, {"rule", 1}}, 21}, Operation::union_},
      {{"random_set", "lattice", {{"n", 20}, {"rule", 4}}, 22}, Operation::intersection},
      {{"pentagram", "rotated", {{"rule", 2}}, 23}, Operation::difference},
  };
  for (const auto& [spec, op] : cases) {
    SCOPED_TRACE(spec.stem());
    const Case c = make_case(spec);
    const std::string text = regression_case_text(c, op, false, {"a comment"});
    const RegressionCase back = read_regression_case(text);
    EXPECT_EQ(back.op, op);
    EXPECT_FALSE(back.regular);
    EXPECT_EQ(back.fill_rule, fill_rule_of(spec));
    EXPECT_EQ(back.parts.has_value(), c.parts.has_value());
    if (c.parts) {
      ASSERT_EQ(back.parts->size(), c.parts->size());
      for (std::size_t i = 0; i < c.parts->size(); ++i) {
        EXPECT_EQ((*back.parts)[i].shell, (*c.parts)[i].shell);
        EXPECT_EQ((*back.parts)[i].holes, (*c.parts)[i].holes);
      }
    } else {
      EXPECT_EQ(back.a.rings, c.a.rings);
      EXPECT_EQ(back.b.rings, c.b.rings);
    }
    BooleanOptions o{Operation::intersection, false, "rational"};  // op comes from the file
    o.exact_coordinates = true;
    EXPECT_EQ(assess(replay_regression_case(back, o).output, case_reference(c, op, false, false)).verdict,
              Verdict::exact_match);
  }
  EXPECT_THROW(read_regression_case("POLYGON ((0 0, 1 0, 1 1, 0 0))\nPOLYGON ((0 0, 1 0, 1 1, 0 0))\nunion\n"
                                    "regular\nfill_rule sideways\n"),
               InvalidInput);
}

}  // namespace
}  // namespace mk::experiments
