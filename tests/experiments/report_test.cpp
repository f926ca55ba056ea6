// Test of the report's section "Cost of exactness by fallback strategy"
// (experiments/report_fallbacks.cpp) on hand-made rows: medians of per-run time ratios to
// `double`, only the generators where a call left its filter, and the share of calls each
// stage decided, summed from the predicate_stages column. [MK89 §3.3]
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

}  // namespace
}  // namespace mk::experiments
