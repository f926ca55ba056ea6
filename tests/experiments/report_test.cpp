// Tests of the report's section "Cost of exactness by fallback strategy"
// (experiments/report_fallbacks.cpp) on hand-made rows: medians of per-run time ratios to
// `double`, only the generators where a call left its filter, and the share of calls each
// stage decided, summed from the predicate_stages column; and of the section "Fill rules
// and union-all sets" (report_sets.cpp): its counts and times per generator, kernel and
// regularity. [MK89 §3.3]
// Preconditions: none.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "experiments/report.hpp"

namespace mk::experiments {
namespace {

ResultRow row(std::uint64_t case_index, const std::string& generator, const std::string& kernel, std::int64_t ns) {
  ResultRow r;
  r.case_index = case_index;
  r.generator = generator;
  r.op = "union";
  r.kernel = kernel;
  r.op_ns = ns;
  return r;
}

std::string section(const std::vector<ResultRow>& rows) {
  std::ostringstream md;
  fallback_section(md, rows);
  return md.str();
}

TEST(ReportFallbacks, RatiosAndStageSharesOnGeneratorsWithFallbacks) {
  std::vector<ResultRow> rows;
  // kettner_grid: two cases; exact costs 1.5 and 2.5 times double (median 2.00), rational
  // 4 and 6 (5.00); interval's calls: 90 filter, 6 interval, 4 mpfr_128 in all.
  for (std::uint64_t c : {0, 1}) {
    rows.push_back(row(c, "kettner_grid", "double", 100));
    auto e = row(c, "kettner_grid", "exact", c == 0 ? 150 : 250);
    e.predicate_calls = 50;
    e.predicate_fallbacks = 5;
    e.predicate_stages = "filter=45;expansion_b=5";
    rows.push_back(e);
    auto i = row(c, "kettner_grid", "interval", 120);
    i.predicate_calls = 50;
    i.predicate_fallbacks = 5;
    i.predicate_stages = "filter=45;interval=3;mpfr_128=2";
    rows.push_back(i);
    rows.push_back(row(c, "kettner_grid", "rational", c == 0 ? 400 : 600));
  }
  // blob: counted, but no call left its filter: not listed.
  rows.push_back(row(2, "blob", "double", 100));
  auto e = row(2, "blob", "exact", 900);
  e.predicate_calls = 10;
  e.predicate_fallbacks = 0;
  e.predicate_stages = "filter=10";
  rows.push_back(e);

  const std::string md = section(rows);
  EXPECT_NE(md.find("## Cost of exactness by fallback strategy"), std::string::npos) << md;
  EXPECT_NE(md.find("| kettner_grid | 2 | 2.00 | 1.20 | 5.00 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| blob |"), std::string::npos) << md;
  EXPECT_NE(md.find("| kettner_grid | filter 90.0%, expansion_b 10.0% | filter 90.0%, interval 6.0%, mpfr_128 4.0% |"),
            std::string::npos)
      << md;
  // Kernels that did not run have no column.
  EXPECT_EQ(md.find("rational-cpp"), std::string::npos) << md;
}

TEST(ReportFallbacks, WithoutCountersEveryGeneratorAndNoShares) {
  std::vector<ResultRow> rows{row(0, "blob", "double", 100), row(0, "blob", "exact", 110),
                              row(0, "blob", "rational-cpp", 1500)};
  const std::string md = section(rows);
  EXPECT_NE(md.find("built without predicate counters"), std::string::npos) << md;
  EXPECT_NE(md.find("| blob | 1 | 1.10 | 15.00 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Share of predicate calls"), std::string::npos) << md;
}

// random_set, regular: exact matched twice (1 and 3 ms: median 2); double gave a valid
// different result, an invalid one and an error (no time); non-regular: one exact run.
// Generators of neither kind are left out.
TEST(ReportSets, CountsAndTimesPerGeneratorKernelAndRegularity) {
  std::vector<ResultRow> rows{row(0, "random_set", "exact", 1000000), row(1, "random_set", "exact", 3000000)};
  for (const Verdict v : {Verdict::valid_different, Verdict::invalid_output, Verdict::error}) {
    ResultRow r = row(0, "random_set", "double", 500000);
    r.verdict = v;
    if (v == Verdict::error) r.op_ns.reset();
    rows.push_back(r);
  }
  ResultRow closed = row(0, "random_set", "exact", 2000000);
  closed.regular = false;
  rows.push_back(closed);
  rows.push_back(row(2, "shared_edge", "exact", 1000));
  const std::string md = fill_and_set_report(rows);
  EXPECT_NE(md.find("## Fill rules and union-all sets"), std::string::npos) << md;
  EXPECT_NE(md.find("| random_set | exact | yes | 2 | 2 | 0 | 0 | 0 | 2 | 0.004 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| random_set | exact | no | 1 | 1 | 0 | 0 | 0 | 2 | 0.002 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| random_set | double | yes | 3 | 0 | 1 | 1 | 1 | 0.5 | 0.001 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("shared_edge"), std::string::npos) << md;
  EXPECT_EQ(fill_and_set_report({row(2, "shared_edge", "exact", 1000)}), "");
}

}  // namespace
}  // namespace mk::experiments
