// The fill-rule options and the parts forms of the command (issue 13): what they accept,
// and clear errors with the documented exit codes for what they do not.
// [BRIEF §1, extended by issue 13] (fill rules) [OGC06-103 §7]
// Preconditions: the built mkbool (MK_CLI_EXE).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

const std::string kBowtie = "POLYGON((0 0,2 2,2 0,0 2,0 0))";

TEST(cliFill, SelfCrossingInputIsRefusedWithoutAFillRuleAndReadWithOne) {
  const ProcessResult refused = run_mkbool({"union", kBowtie, square_a});
  EXPECT_EQ(refused.exit_code, 3) << describe(refused);
  EXPECT_NE(refused.err.find("crosses"), std::string::npos) << describe(refused);
  const ProcessResult read = run_mkbool({"union", kBowtie, square_a, "--fill-rule", "evenodd", "--stats"});
  ASSERT_EQ(read.exit_code, 0) << describe(read);
  // The square covers the bowtie: evenodd gives the square, area 4.
  EXPECT_NE(read.err.find("\"area_exact\":\"4\""), std::string::npos) << describe(read);
}

TEST(cliFill, PartsFormsReadFilesOfOneWktPerLineAndGeoJson) {
  TempDir dir;
  const std::string lines = (dir.path() / "parts.wkt").string();
  {
    std::ofstream f(lines);
    f << "POLYGON((0 0,2 0,2 2,0 2,0 0))\n\nPOLYGON((1 1,3 1,3 3,1 3,1 1))\nMULTIPOLYGON(((5 5,6 5,6 6,5 6,5 5)))\n";
  }
  const ProcessResult u = run_mkbool({"union-all", lines, "--stats"});
  ASSERT_EQ(u.exit_code, 0) << describe(u);
  EXPECT_NE(u.err.find("\"area_exact\":\"8\""), std::string::npos) << describe(u);
  const ProcessResult i = run_mkbool({"intersection-all", lines});
  ASSERT_EQ(i.exit_code, 0) << describe(i);
  EXPECT_EQ(i.out, "POLYGON EMPTY\n");
  const std::string features =
      R"({"type":"FeatureCollection","features":[)"
      R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}},)"
      R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[0,2],[2,2],[2,0],[0,0]]]}}]})";
  const ProcessResult g = run_mkbool({"union-all", "-", "--format", "geojson", "--stats"}, features);
  ASSERT_EQ(g.exit_code, 0) << describe(g);
  EXPECT_NE(g.err.find("\"area_exact\":\"4\""), std::string::npos) << describe(g);  // one square, twice
}

TEST(cliFill, BatchLinesMayNameAFillRule) {
  const std::string lines =
      R"x({"id":1,"op":"union","a_wkt":"POLYGON((0 0,2 2,2 0,0 2,0 0))","b_wkt":"POLYGON EMPTY","fill_rule":"positive"})x"
      "\n"
      R"x({"id":2,"op":"union","a_wkt":"POLYGON((0 0,2 2,2 0,0 2,0 0))","b_wkt":"POLYGON EMPTY"})x"
      "\n"
      R"x({"id":3,"op":"union","a_wkt":"POLYGON((0 0,2 2,2 0,0 2,0 0))","b_wkt":"POLYGON EMPTY","fill_rule":"odd"})x"
      "\n";
  const ProcessResult r = run_mkbool({"batch", "-"}, lines);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto first = r.out.find("\"id\":1");
  const auto second = r.out.find("\"id\":2");
  const auto third = r.out.find("\"id\":3");
  ASSERT_TRUE(first != std::string::npos && second != std::string::npos && third != std::string::npos) << r.out;
  const std::string one = r.out.substr(first, second - first);
  EXPECT_NE(one.find("\"area_exact\":\"1\""), std::string::npos) << one;  // the left triangle
  EXPECT_NE(r.out.substr(second, third - second).find("crosses"), std::string::npos) << r.out;
  EXPECT_NE(r.out.substr(third).find("unknown fill_rule 'odd'"), std::string::npos) << r.out;
}

// Non-regular with a fill rule: the closed-set operation of the regions' closures keeps the
// edge where the bowtie's right triangle (1 1, 2 2, 2 0) touches the square beside it, and
// intersection-all keeps the edge two parts share.
TEST(cliFill, NonRegularKeepsWhereRegionsOnlyTouch) {
  const ProcessResult edge =
      run_mkbool({"intersection", kBowtie, "POLYGON((2 0,3 0,3 2,2 2,2 0))", "--fill-rule", "evenodd", "--non-regular"});
  EXPECT_EQ(edge.exit_code, 0) << describe(edge);
  EXPECT_EQ(edge.out, "GEOMETRYCOLLECTION (LINESTRING (2 0, 2 2))\n") << describe(edge);
  const std::string parts = "MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((1 0,2 0,2 1,1 1,1 0)))";
  const ProcessResult shared = run_mkbool({"intersection-all", parts, "--non-regular"});
  EXPECT_EQ(shared.exit_code, 0) << describe(shared);
  EXPECT_EQ(shared.out, "GEOMETRYCOLLECTION (LINESTRING (1 0, 1 1))\n") << describe(shared);
  const ProcessResult regular = run_mkbool({"intersection-all", parts});
  EXPECT_EQ(regular.out, "POLYGON EMPTY\n") << describe(regular);
}

// The parts forms round as the binary operations do: --grid snaps the result onto multiples
// of G. A = the rectangle 0..3 x 0..1, B = the triangle (1 -1, 2.1 2.3, 0.2 2): their
// edges cross at x = 11/15, 4/3 (y = 0) and 7/15, 5/3 (y = 1), each in the hot pixel of the
// nearest multiple of 0.5 (0.5, 1.5, 0.5, 1.5); 2.1 2.3 and 0.2 2 go to 2 2.5 and 0 2.
TEST(cliFill, PartsFormsTakeTheRoundingOptions) {
  const std::string parts = "MULTIPOLYGON(((0 0,3 0,3 1,0 1,0 0)),((1 -1,2.1 2.3,0.2 2,1 -1)))";
  const std::string snapped = "POLYGON ((0 0, 0.5 0, 1 -1, 1.5 0, 3 0, 3 1, 1.5 1, 2 2.5, 0 2, 0.5 1, 0 1, 0 0))\n";
  const ProcessResult u = run_mkbool({"union-all", parts, "--grid", "0.5"});
  ASSERT_EQ(u.exit_code, 0) << describe(u);
  EXPECT_EQ(u.out, snapped) << describe(u);
  const ProcessResult binary =
      run_mkbool({"union", "POLYGON((0 0,3 0,3 1,0 1,0 0))", "POLYGON((1 -1,2.1 2.3,0.2 2,1 -1))", "--grid", "1/2"});
  EXPECT_EQ(binary.out, snapped) << describe(binary);
  const ProcessResult nearest = run_mkbool({"union-all", parts, "--rounding", "nearest"});
  ASSERT_EQ(nearest.exit_code, 0) << describe(nearest);
  EXPECT_NE(nearest.out.find("0.7333333333333334 0"), std::string::npos) << describe(nearest);
  const ProcessResult both = run_mkbool({"make-valid", kBowtie, "--rounding", "nearest", "--grid", "1"});
  EXPECT_EQ(both.exit_code, 2) << describe(both);
  EXPECT_NE(both.err.find("--grid snaps the result"), std::string::npos) << describe(both);
  const ProcessResult bad = run_mkbool({"intersection-all", parts, "--grid", "0"});
  EXPECT_EQ(bad.exit_code, 2) << describe(bad);
}

// Batch lines run the parts forms too: "op" union-all, intersection-all or make-valid with
// the input as "wkt", "parts" (an array of WKT) or "geojson". Areas derived by hand: two
// 2 x 2 squares overlapping in a unit square (union 7, intersection 1), the bowtie's two
// triangles (2 under nonzero), a 2 x 2 square (4); bad lines get their own errors.
TEST(cliFill, BatchLinesRunThePartsForms) {
  using Json = nlohmann::json;
  const std::string squares = "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))";
  const Json square = Json::parse(R"({"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]})");
  const std::vector<Json> lines{
      {{"id", 1}, {"op", "union-all"}, {"wkt", squares}},
      {{"id", 2}, {"op", "intersection-all"}, {"parts", {"POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((1 1,3 1,3 3,1 3,1 1))"}}},
      {{"id", 3}, {"op", "make-valid"}, {"wkt", kBowtie}, {"fill_rule", "nonzero"}},
      {{"id", 4}, {"op", "union-all"}, {"geojson", {{"type", "FeatureCollection"}, {"features", {{{"type", "Feature"}, {"properties", Json::object()}, {"geometry", square}}}}}}},
      {{"id", 5}, {"op", "union-all"}, {"a_wkt", square_a}, {"b_wkt", square_a}},
      {{"id", 6}, {"op", "union-all"}, {"parts", {square_a, 3}}},
      {{"id", 7}, {"op", "intersection-all"}, {"parts", Json::array()}},
      {{"id", 8}, {"op", "union-all"}, {"wkt", square_a}, {"geojson", square}},
      {{"id", 9}, {"op", "union"}, {"wkt", squares}},
      {{"id", 10}, {"op", "union-all"}, {"wkt", "POLYGON((0 0,1 0,1 1))"}}};
  std::string input;
  for (const Json& l : lines) input += l.dump() + "\n";
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  std::vector<Json> out;
  std::istringstream text(r.out);
  for (std::string line; std::getline(text, line);) out.push_back(Json::parse(line));
  ASSERT_EQ(out.size(), lines.size()) << r.out;
  const char* areas[] = {"7", "1", "2", "4"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i]["area_exact"], areas[i]) << out[i].dump();
    EXPECT_EQ(out[i]["valid"], true) << out[i].dump();
    EXPECT_FALSE(out[i].contains("error")) << out[i].dump();
  }
  EXPECT_EQ(out[0]["result_wkt"], "POLYGON ((0 2, 0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2))");
  const char* errors[] = {"missing the input", "\"parts\"[1] is not a WKT string", "needs at least one polygon",
                          "not several", "missing \"a_wkt\"", "ring has 3 coordinates"};
  for (int i = 4; i < 10; ++i) {
    ASSERT_TRUE(out[i].contains("error")) << out[i].dump();
    EXPECT_NE(out[i]["error"].get<std::string>().find(errors[i - 4]), std::string::npos) << out[i].dump();
    EXPECT_TRUE(out[i]["result_wkt"].is_null()) << out[i].dump();
  }
}

TEST(cliFill, BadArgumentsAndInputGetClearErrors) {
  const ProcessResult rule = run_mkbool({"make-valid", kBowtie, "--fill-rule", "odd"});
  EXPECT_EQ(rule.exit_code, 2) << describe(rule);
  const ProcessResult missing = run_mkbool({"union-all"});
  EXPECT_EQ(missing.exit_code, 2) << describe(missing);
  const ProcessResult native = run_mkbool({"make-valid", R"({"rings":[[[0,0],[1,0],[1,1]]],"type":"island"})"});
  EXPECT_EQ(native.exit_code, 3) << describe(native);
  EXPECT_NE(native.err.find("native JSON has no parts"), std::string::npos) << describe(native);
  const ProcessResult bad_line = run_mkbool({"union-all", "-"}, "POLYGON((0 0,1 0,1 1,0 0))\nPOLYGON((0 0,1 0,1 1))\n");
  EXPECT_EQ(bad_line.exit_code, 3) << describe(bad_line);
  EXPECT_NE(bad_line.err.find("line 2: "), std::string::npos) << describe(bad_line);
  const ProcessResult open = run_mkbool({"union-all", "POLYGON((0 0,1 0,1 1))"});
  EXPECT_EQ(open.exit_code, 3) << describe(open);
  const ProcessResult empty = run_mkbool({"intersection-all", "POLYGON EMPTY"});
  EXPECT_EQ(empty.exit_code, 3) << describe(empty);
}

}  // namespace
}  // namespace mk::test
