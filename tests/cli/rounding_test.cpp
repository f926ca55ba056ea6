// The command's rounding modes and exact chaining: a near-degenerate case whose nearest
// doubles are invalid is snap-rounded by default and exits 4 with a warning under
// --rounding nearest; --grid puts the output on the grid; (A ∪ B) ∩ C chained through
// --format json equals the hand-derived exact answer. [BRIEF §6a] [Ho99]
// Preconditions: the mkbool executable is built (MK_CLI_EXE).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

// Two triangles whose intersection's nearest doubles are not a valid polygon (B's vertices
// a few ulps off A's edges; found with tests/api/near_degenerate.hpp, variant 0, seed 7).
const std::string sliver_a =
    "POLYGON ((0.96537237542267185 0.22739579952077785, 0.46786665351848666 0.14712530555449221, "
    "0.64551903878599848 0.038874529127181534, 0.96537237542267185 0.22739579952077785))";
const std::string sliver_b =
    "POLYGON ((0.79810829600868205 0.20040843096150171, 0.68449956803149792 0.061849618182837497, "
    "0.53908903038851086 0.10372663357173791, 0.79810829600868205 0.20040843096150171))";

TEST(cliRounding, NearestExitsFourWithAWarningAndCertifiedSnaps) {
  const std::string& a = sliver_a;
  const std::string& b = sliver_b;
  const ProcessResult nearest = run_mkbool({"intersection", a, b, "--rounding", "nearest"});
  EXPECT_EQ(nearest.exit_code, 4) << describe(nearest);
  EXPECT_NE(nearest.err.find("mkbool: warning: "), std::string::npos) << describe(nearest);
  EXPECT_FALSE(nearest.out.empty());
  const ProcessResult certified = run_mkbool({"intersection", a, b, "--stats"});
  EXPECT_EQ(certified.exit_code, 0) << describe(certified);
  const auto stats = nlohmann::json::parse(certified.err);
  EXPECT_EQ(stats["rounded_valid"], false);
  EXPECT_EQ(stats["rounding"]["mode"], "certified");
  EXPECT_EQ(stats["rounding"]["snapped"], true);
  EXPECT_EQ(stats["rounding"]["valid"], true);
  EXPECT_LE(stats["rounding"]["max_displacement"].get<double>(), 0.7072);
}

TEST(cliRounding, GridAndBadGrid) {
  const ProcessResult r = run_mkbool({"union", "POLYGON ((0 0, 3 0, 0 3, 0 0))", "POLYGON ((1 1, 4 1, 1 4, 1 1))", "--grid", "0.5"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "POLYGON ((0 0, 3 0, 2 1, 4 1, 1 4, 1 2, 0 3, 0 0))\n");
  const ProcessResult third = run_mkbool({"union", "POLYGON ((0 0, 3 0, 0 3, 0 0))", "POLYGON ((1 1, 4 1, 1 4, 1 1))", "--grid", "1/3", "--stats"});
  EXPECT_EQ(third.exit_code, 0) << describe(third);
  EXPECT_EQ(nlohmann::json::parse(third.err)["rounding"]["grid"], "1/3");
  for (const char* bad : {"0", "-1", "abc", "1/0"}) {
    const ProcessResult e = run_mkbool({"union", "POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 1 0, 0 1, 0 0))", "--grid", bad});
    EXPECT_EQ(e.exit_code, 2) << bad << "\n" << describe(e);
  }
  const ProcessResult both = run_mkbool({"union", "POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 1 0, 0 1, 0 0))", "--grid", "1", "--rounding", "nearest"});
  EXPECT_EQ(both.exit_code, 2) << describe(both);
  // A grid far finer than the doubles at the result's scale: exit 1, and a message that names
  // both in a form a reader can take in (not 300 digits, not a magnitude of "0.000000").
  const ProcessResult fine = run_mkbool({"union", "POLYGON ((0 0, 3e-10 0, 0 3e-10, 0 0))",
                                         "POLYGON ((1e-10 1e-10, 4e-10 1e-10, 1e-10 4e-10, 1e-10 1e-10))", "--grid", "1e-300"});
  EXPECT_EQ(fine.exit_code, 1) << describe(fine);
  EXPECT_NE(fine.err.find("grid about 1e-300 is too fine for coordinates of magnitude 4e-10"), std::string::npos)
      << describe(fine);
  EXPECT_LT(fine.err.size(), 200u) << describe(fine);
  const ProcessResult fraction = run_mkbool({"union", "POLYGON ((0 0, 3 0, 0 3, 0 0))", "POLYGON ((1 1, 4 1, 1 4, 1 1))",
                                             "--grid", "1/9007199254740993"});
  EXPECT_EQ(fraction.exit_code, 1) << describe(fraction);
  EXPECT_NE(fraction.err.find("grid 1/9007199254740993 is too fine for coordinates of magnitude 4 "), std::string::npos)
      << describe(fraction);
}

// A = x + y <= 3 (triangle), B = y <= 2x/3 (triangle), C = [1, 2] x [0, 2]. A ∪ B has the
// crossing (9/5, 6/5), not a double; (A ∪ B) ∩ C is y <= 3 - x on [1, 9/5] and y <= 2x/3
// on [9/5, 2]: area 64/50 + 19/75 = 23/15 (integrated by hand).
TEST(cliRounding, ChainThroughNativeJsonIsExact) {
  TempDir dir;
  const std::string ab = dir.file("ab.json");
  const ProcessResult first = run_mkbool({"union", "POLYGON ((0 0, 3 0, 0 3, 0 0))", "POLYGON ((0 0, 3 0, 3 2, 0 0))",
                                          "--format", "json", "-o", ab});
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  const ProcessResult second =
      run_mkbool({"intersection", ab, "POLYGON ((1 0, 2 0, 2 2, 1 2, 1 0))", "--stats", "--format", "json"});
  ASSERT_EQ(second.exit_code, 0) << describe(second);
  const auto stats = nlohmann::json::parse(second.err);
  EXPECT_EQ(stats["area_exact"], "23/15");
  EXPECT_EQ(stats["kernel"], "rational");  // the input had non-double coordinates
  const auto out = nlohmann::json::parse(second.out);
  bool found = false;
  for (const auto& v : out["polygons"][0]["exact"]) found = found || (v[0] == "9/5" && v[1] == "6/5");
  EXPECT_TRUE(found) << second.out;
  // Read back once more (from standard input): the same region.
  const ProcessResult third = run_mkbool({"intersection", "-", "POLYGON ((0 0, 5 0, 5 5, 0 5, 0 0))", "--stats"}, second.out);
  ASSERT_EQ(third.exit_code, 0) << describe(third);
  EXPECT_EQ(nlohmann::json::parse(third.err)["area_exact"], "23/15");
}

TEST(cliRounding, ExactStringsInNativeJsonInput) {
  const ProcessResult r = run_mkbool(
      {"intersection", R"({"type": "island", "rings": [[["0", "0"], ["1/3", "0"], ["0.1", "2/3"]]]})",
       "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))", "--stats"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(nlohmann::json::parse(r.err)["area_exact"], "1/9");  // (1/2) (1/3) (2/3)
  const ProcessResult bad = run_mkbool({"intersection", R"({"rings": [[["1/0", "0"], [1, 0], [0, 1]]]})", "POLYGON ((0 0, 1 0, 0 1, 0 0))"});
  EXPECT_EQ(bad.exit_code, 3) << describe(bad);
}

}  // namespace
}  // namespace mk::test
