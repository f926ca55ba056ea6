// Tests of the generators: every variant builds a valid input, the same seed gives the same
// case, the lattice generators really contain their degeneracy, and sweep plans are
// reproducible and shard into disjoint parts. [MK89 §2.2]
// Preconditions: none.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/error.hpp"
#include "experiments/generators.hpp"
#include "experiments/operations.hpp"
#include "experiments/runner.hpp"
#include "experiments/verdict.hpp"

namespace mk::experiments {
namespace {

std::vector<std::pair<std::string, std::int64_t>> small_params(std::string_view generator, int s) {
  if (generator == "blob" || generator == "star") return {{"n", 12 + s}};
  if (generator == "kettner_grid") return {{"i", 3 * s}, {"j", 5 * s}};
  if (generator == "ulp_perturbed") return {{"k", s - 1}};
  if (generator == "grid_random") return {{"grid", s % 2 == 0 ? 6 : 10}};
  if (generator == "magnitude") return {{"e", s % 2 == 0 ? 150 : -150}};
  return {};
}

// magnitude: the lattice case times 10^e (near-integer multiples of 1e150 here, integers at
// e = 0), and the exact kernel's results at 10^300 and 10^-300, where every product of two
// coordinates overflows or underflows, match the exact reference.
TEST(Generators, MagnitudeScalesALatticeCaseAndTheExactKernelKeepsUp) {
  const Generator& g = find_generator("magnitude");
  for (const auto v : g.variants) {
    const Case unit = make_case({"magnitude", std::string(v), {{"e", 0}}, 11});
    const Case big = make_case({"magnitude", std::string(v), {{"e", 150}}, 11});
    ASSERT_EQ(unit.a.rings.size(), big.a.rings.size()) << v;
    for (std::size_t r = 0; r < unit.a.rings.size(); ++r) {
      ASSERT_EQ(unit.a.rings[r].size(), big.a.rings[r].size()) << v;
      for (std::size_t k = 0; k < unit.a.rings[r].size(); ++k) {
        const Point u = unit.a.rings[r][k], w = big.a.rings[r][k];
        EXPECT_EQ(u.x, std::round(u.x)) << v;
        EXPECT_EQ(w.x, u.x * 1e150) << v;  // the same double operation
        EXPECT_EQ(w.y, u.y * 1e150) << v;
      }
    }
  }
  RunOptions o;
  o.kernels = {"exact"};
  o.ops = {Operation::intersection, Operation::union_, Operation::difference};
  o.regular = {true};
  int runs = 0;
  for (const std::int64_t e : {300, -300}) {
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      const CaseSpec spec{"magnitude", std::string(g.variants[seed % g.variants.size()]), {{"e", e}}, mix_seed(3, "magnitude", seed)};
      const Case c = make_case(spec);
      run_built_case({0, spec}, c, o, 0, [](std::size_t) {}, [&](const ResultRow& r) {
        if (r.kernel != "exact") return;
        ++runs;
        EXPECT_TRUE(r.verdict == Verdict::exact_match || r.verdict == Verdict::refused) << to_csv(r);
      });
    }
  }
  EXPECT_EQ(runs, 2 * 12 * 3);
}

TEST(Generators, EveryVariantBuildsAValidInputReproducibly) {
  for (const Generator& g : generators()) {
    for (const auto v : g.variants) {
      for (int s = 0; s < 4; ++s) {
        const CaseSpec spec{std::string(g.name), std::string(v), small_params(g.name, s), mix_seed(7, g.name, s)};
        SCOPED_TRACE(spec.generator + " " + spec.variant + " seed " + std::to_string(spec.seed));
        const Case c = make_case(spec);
        EXPECT_GT(c.size(), 0u);
        const Case again = make_case(spec);
        EXPECT_EQ(c.a.rings, again.a.rings);
        EXPECT_EQ(c.b.rings, again.b.rings);
        EXPECT_EQ(c.a.type, again.a.type);
        EXPECT_NO_THROW(case_reference(c, Operation::intersection, true, true));
        EXPECT_EQ(c.parts.has_value(), is_set_generator(spec.generator));
      }
    }
  }
}

// The validity check must accept the exact result wherever its rounding keeps it valid (as
// the library reports): otherwise invalid_output verdicts would be false alarms.
TEST(Generators, ValidityAcceptsEveryValidExactResult) {
  std::size_t checked = 0;
  for (const Generator& g : generators()) {
    for (const auto v : g.variants) {
      for (int s = 0; s < 2; ++s) {
        const CaseSpec spec{std::string(g.name), std::string(v), small_params(g.name, s), mix_seed(9, g.name, s)};
        const Case c = make_case(spec);
        for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                                   Operation::symmetric_difference}) {
          for (const bool regular : {true, false}) {
            if (!runs_operation(spec, op)) continue;  // set cases: union_all and intersection_all
            const ExactResult ref = case_reference(c, op, regular, false);
            if (ref.output.rounded_valid != true) continue;
            std::string why;
            EXPECT_TRUE(is_valid_output(ref.output, ccw_type_of(ref), &why))
                << spec.generator << " " << spec.variant << " seed " << spec.seed << " " << run_operation_name(spec, op)
                << (regular ? "" : " non-regular") << ": " << why;
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 300u);
}

TEST(Generators, UnknownNamesAreRejected) {
  EXPECT_THROW(make_case({"no_such_generator", "x", {}, 1}), std::invalid_argument);
  EXPECT_THROW(make_case({"shared_edge", "no_such_variant", {}, 1}), std::invalid_argument);
}

using QPoint = RationalPoint;

bool is_inside_segment(const QPoint& a, const QPoint& b, const QPoint& p) {
  return RationalKernel::orient2d(a, b, p) == Sign::zero && !(p == a) && !(p == b) &&
         std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

template <class F>
void for_each_edge(const Polygon& p, F&& f) {
  for (const auto& r : p.rings) {
    for (std::size_t i = 0; i < r.size(); ++i) f(RationalKernel::point(r[i]), RationalKernel::point(r[(i + 1) % r.size()]));
  }
}

TEST(Generators, LatticeCasesContainTheirDegeneracy) {
  for (int s = 0; s < 10; ++s) {
    const auto seed = mix_seed(11, "degenerate", s);
    {
      const Case c = make_case({"shared_vertex", "outside", {}, seed});
      std::set<std::pair<double, double>> va;
      for (const auto& p : c.a.rings[0]) va.insert({p.x, p.y});
      int shared = 0;
      for (const auto& p : c.b.rings[0]) shared += va.count({p.x, p.y}) > 0 ? 1 : 0;
      EXPECT_EQ(shared, 1) << "shared_vertex seed " << seed;
    }
    {
      const Case c = make_case({"vertex_on_edge", "outside", {}, seed});
      int on = 0;
      for_each_edge(c.a, [&](const QPoint& a, const QPoint& b) {
        for (const auto& p : c.b.rings[0]) on += is_inside_segment(a, b, RationalKernel::point(p)) ? 1 : 0;
      });
      EXPECT_EQ(on, 1) << "vertex_on_edge seed " << seed;
    }
    {
      const Case c = make_case({"collinear_overlap", s % 2 == 0 ? "same" : "opposite", {}, seed});
      int overlaps = 0;
      for_each_edge(c.a, [&](const QPoint& a, const QPoint& b) {
        for_each_edge(c.b, [&](const QPoint& p, const QPoint& q) {
          const bool p_in = is_inside_segment(a, b, p) && RationalKernel::orient2d(a, b, q) == Sign::zero;
          const bool q_in = is_inside_segment(a, b, q) && RationalKernel::orient2d(a, b, p) == Sign::zero;
          overlaps += p_in || q_in ? 1 : 0;
        });
      });
      EXPECT_GE(overlaps, 1) << "collinear_overlap seed " << seed;
    }
    {
      const Case c = make_case({"ulp_perturbed", "outside_triangle", {{"k", 0}}, seed});
      int on = 0;
      for_each_edge(c.a, [&](const QPoint& a, const QPoint& b) {
        for (const auto& p : c.b.rings[0]) on += is_inside_segment(a, b, RationalKernel::point(p)) ? 1 : 0;
      });
      EXPECT_EQ(on, 1) << "ulp_perturbed k=0 is vertex_on_edge, seed " << seed;
      const Case moved = make_case({"ulp_perturbed", "outside_triangle", {{"k", 3}}, seed});
      int still = 0;
      for_each_edge(moved.a, [&](const QPoint& a, const QPoint& b) {
        for (const auto& p : moved.b.rings[0]) still += is_inside_segment(a, b, RationalKernel::point(p)) ? 1 : 0;
      });
      EXPECT_EQ(still, 0) << "ulp_perturbed k=3 leaves the edge, seed " << seed;
    }
  }
}

TEST(Generators, KettnerGridMovesPByUlps) {
  const Case c = make_case({"kettner_grid", "shared_edge_a", {{"i", 2}, {"j", 1}}, 1});
  const Point p = c.b.rings[0][2];
  EXPECT_EQ(p.x, std::nextafter(std::nextafter(0.5, 1.0), 1.0));
  EXPECT_EQ(p.y, std::nextafter(0.5, 1.0));
}

TEST(Plan, QuickPlanIsReproducibleWithDistinctSeeds) {
  const auto a = plan_sweep({SweepLevel::quick, 0, 1, {}});
  const auto b = plan_sweep({SweepLevel::quick, 0, 1, {}});
  ASSERT_EQ(a.size(), b.size());
  std::set<std::pair<std::string, std::uint64_t>> seeds;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].seed, b[i].seed);
    EXPECT_EQ(a[i].params_text(), b[i].params_text());
    EXPECT_TRUE(seeds.insert({a[i].generator, a[i].seed}).second) << a[i].generator << " " << a[i].seed;
    names.insert(a[i].generator);
  }
  // Every generator has cases, except `cases`, which runs only the user's file (run --cases),
  // and the fill generators, which run when named; the set generators run in every plan.
  std::size_t fill = 0;
  for (const Generator& g : generators()) {
    fill += is_fill_generator(g.name) ? 1 : 0;
    if (is_set_generator(g.name)) {
      EXPECT_TRUE(names.count(std::string(g.name))) << g.name;
    }
  }
  EXPECT_GT(fill, 0u);
  EXPECT_EQ(names.size(), generators().size() - 1 - fill);
  EXPECT_FALSE(names.count("cases"));
  EXPECT_TRUE(names.count("reported"));
  EXPECT_NE(plan_sweep({SweepLevel::quick, 0, 2, {}})[0].seed, a[0].seed);
}

TEST(Plan, ShardsPartitionThePlan) {
  const auto plan = plan_sweep({SweepLevel::quick, 1, 1, {"shared_edge", "kettner_grid"}});
  std::set<std::uint64_t> seen;
  for (std::size_t i = 0; i < 3; ++i) {
    for (const auto& c : select_shard(plan, parse_shard(std::to_string(i) + "/3"))) {
      EXPECT_TRUE(seen.insert(c.index).second);
      EXPECT_EQ(c.index % 3, i);
    }
  }
  EXPECT_EQ(seen.size(), plan.size());
  EXPECT_THROW(parse_shard("3/3"), std::invalid_argument);
  EXPECT_THROW(parse_shard("1-3"), std::invalid_argument);
  EXPECT_THROW(plan_sweep({SweepLevel::quick, 1, 1, {"nope"}}), std::invalid_argument);
}

TEST(Plan, ParamsRoundTrip) {
  const CaseSpec s{"kettner_grid", "shared_edge_a", {{"i", 4}, {"j", -8}}, 3};
  EXPECT_EQ(s.params_text(), "i=4;j=-8");
  EXPECT_EQ(parse_params(s.params_text()), s.params);
  EXPECT_TRUE(parse_params("").empty());
  EXPECT_THROW(parse_params("i=x"), std::invalid_argument);
}

}  // namespace
}  // namespace mk::experiments
