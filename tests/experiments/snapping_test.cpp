// Tests of the harness's rounding research (issue 12): on a small sweep of near-degenerate
// generators the exact kernel's written output is valid for GEOS too (geos_valid filled and
// true, left empty out of GEOS's range), and the report's rounding table counts it.
// [Ho99] [HP02] [BRIEF §6a]
// Preconditions: none.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

#include "api/mkbool.hpp"
#include "experiments/generators.hpp"
#include "experiments/peers/peers.hpp"
#include "experiments/report_rounding.hpp"
#include "experiments/runner.hpp"

namespace mk::experiments {
namespace {

// The quick plan of the near-degenerate generators where nearest rounding breaks results
// (experiments/README.md), one seed, kernel exact, in this process.
std::vector<ResultRow> small_sweep() {
  const auto plan = plan_sweep({SweepLevel::quick, 1, 1, {"ulp_perturbed", "kettner_grid"}});
  RunOptions o;
  o.kernels = {"exact"};
  o.isolate = false;
  return run_sweep(select_shard(plan, {}), o, "");
}

TEST(Snapping, WrittenOutputIsValidForGeos) {
  const std::vector<ResultRow> rows = small_sweep();
  std::size_t snapped = 0, bounded = 0, geos_checked = 0;
  std::map<std::string, std::set<std::uint64_t>> snapped_cases;  // generator -> cases
  for (const auto& r : rows) {
    ASSERT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
    if (!r.certified_valid) continue;  // unbounded result
    ++bounded;
    EXPECT_EQ(r.certified_valid, std::optional<bool>(true)) << to_csv(r);
    if (r.certified_snapped == true) {
      ++snapped;
      EXPECT_EQ(r.nearest_valid, std::optional<bool>(false)) << to_csv(r);  // snapping only when needed
      snapped_cases[r.generator].insert(r.case_index);
    }
    if (is_peer("geos")) {
      // Issue 12's "done": the written output is valid by GEOS's isValid as well.
      EXPECT_EQ(r.geos_valid, std::optional<bool>(true)) << to_csv(r);
      geos_checked += r.geos_valid.has_value();
    } else {
      EXPECT_FALSE(r.geos_valid) << to_csv(r);
    }
  }
  std::printf("small sweep (quick, base seed 1, 1 seed): %zu exact runs, %zu bounded, %zu snapped, %zu checked by GEOS\n",
              rows.size(), bounded, snapped, geos_checked);
  ASSERT_GT(snapped, 0u) << "no result snapped: the test needs a case where nearest rounding is invalid";
  if (is_peer("geos")) {
    EXPECT_EQ(geos_checked, bounded);
  }

  const std::string md = rounding_report(rows);
  EXPECT_NE(md.find("| certified: GEOS invalid |"), std::string::npos);
  if (is_peer("geos")) {
    EXPECT_NE(md.find(" | 0 of " + std::to_string(bounded) + " | "), std::string::npos) << md;
  }
}

TEST(Snapping, GeosIsNotAskedBeyondItsRange) {
  // Two overlapping squares at 1e-250: GEOS's orientation products underflow there, so the
  // written output's geos_valid stays empty; the same squares at 1 are checked.
  const auto squares = [](double s) {
    Case c;
    c.spec = {"cases", "squares", {}, 0};
    c.a.rings = {{{0, 0}, {2 * s, 0}, {2 * s, 2 * s}, {0, 2 * s}}};
    c.b.rings = {{{s, s}, {3 * s, s}, {3 * s, 3 * s}, {s, 3 * s}}};
    return c;
  };
  RunOptions o;
  o.kernels = {"exact", "double"};
  o.ops = {Operation::union_};
  o.regular = {true};
  for (const double s : {1.0, 1e-250}) {
    std::vector<ResultRow> rows;
    run_built_case({0, squares(s).spec}, squares(s), o, 0, [](std::size_t) {}, [&](const ResultRow& r) { rows.push_back(r); });
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& r : rows) {
      if (r.kernel == "exact") {
        EXPECT_EQ(r.verdict, Verdict::exact_match) << to_csv(r);
      }
      const bool asked = is_peer("geos") && r.kernel == "exact" && s == 1.0;
      EXPECT_EQ(r.geos_valid, asked ? std::optional<bool>(true) : std::nullopt) << "scale " << s << ": " << to_csv(r);
    }
  }
}

}  // namespace
}  // namespace mk::experiments
