// Batch mode of the command (issue 3): one output line per input line, in order, with exact
// areas for exact kernels; a bad line gives an error line and never stops the batch.
// [MK89 §2.3] (operations; symmetric difference added) [MK89 §3.3] (rounded validity)
// Preconditions: the built mkbool (MK_CLI_EXE) and the library (for kernel_names()).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "tests/cli/canonical_wkt.hpp"
#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

using Json = nlohmann::ordered_json;  // keeps the order of the keys as written

std::string case_line(const Json& id, const std::string& op, const std::string& a, const std::string& b) {
  return Json{{"id", id}, {"op", op}, {"a_wkt", a}, {"b_wkt", b}}.dump() + "\n";
}

std::vector<Json> parse_lines(const std::string& text) {
  std::vector<Json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(Json::parse(line));
  return lines;
}

TEST(cliBatch, BadLineInTheMiddleDoesNotStopTheBatch) {
  const std::string input = case_line(1, "intersection", square_a, square_b) + "{\"id\": 2, \"op\": \"union\",\n" +
                            case_line("three", "union", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(lines[0]["id"], 1);
  EXPECT_FALSE(lines[0].contains("error"));
  EXPECT_EQ(canonical_wkt(lines[0]["result_wkt"].get<std::string>()), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))"));
  EXPECT_TRUE(lines[1]["id"].is_null());
  EXPECT_EQ(lines[1]["line"], 2);
  EXPECT_NE(lines[1]["error"].get<std::string>().find("malformed JSON"), std::string::npos) << lines[1];
  EXPECT_TRUE(lines[1]["result_wkt"].is_null());
  EXPECT_EQ(lines[2]["id"], "three");
  EXPECT_EQ(lines[2]["area"], 7.0);
}

// A batch file is JSON Lines text: binary data is refused at its first NUL byte with exit 3,
// never read to its end (/dev/zero has none) or until memory runs out.
TEST(cliBatch, BinaryInputIsRefusedAtItsFirstNulByte) {
  for (const std::string device : {"/dev/zero", "/dev/urandom"}) {
    const ProcessResult r = run_mkbool({"batch", device});
    EXPECT_EQ(r.exit_code, 3) << device << " " << describe(r);
    EXPECT_NE(r.err.find("NUL byte"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  }
  const ProcessResult r = run_mkbool({"batch", "-"}, case_line(1, "union", square_a, square_b) + std::string(3, '\0'));
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_NE(r.err.find("NUL byte"), std::string::npos) << r.err;
}

TEST(cliBatch, EveryFailingCaseGivesItsOwnErrorLine) {
  const std::string input = case_line(1, "nope", square_a, square_b) +                                //
                            case_line(2, "union", "POLYGON((0 0,1 0,0 1,1 1,0 0))", square_b) +          //
                            case_line(3, "union", "POLYGON((0 0,2 0,2 2,0 2))", square_b) +              //
                            "[1, 2]\n" +                                                                //
                            "{\"id\": 5, \"op\": \"union\", \"b_wkt\": \"POLYGON EMPTY\"}\n" +          //
                            "{\"id\": 6, \"op\": \"union\", \"a_wkt\": 7, \"b_wkt\": \"POLYGON EMPTY\"}\n" +  //
                            case_line(7, "union", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 7u) << r.out;
  const char* expected[] = {"unknown op 'nope'",       "crosses",    "a_wkt: WKT line 1, column 22",
                            "must be a JSON object", "missing \"a_wkt\"", "\"a_wkt\" is not a string"};
  for (std::size_t i = 0; i < 6; ++i) {
    ASSERT_TRUE(lines[i].contains("error")) << lines[i];
    EXPECT_NE(lines[i]["error"].get<std::string>().find(expected[i]), std::string::npos) << lines[i];
    EXPECT_EQ(lines[i]["line"], i + 1);
  }
  EXPECT_FALSE(lines[6].contains("error"));
  EXPECT_EQ(lines[6]["id"], 7);
}

// A case line naming a member twice ("op" twice: nlohmann kept the last and ran that
// operation) is refused with its own error line; the next line still runs. [RFC8259 §4]
TEST(cliBatch, ARepeatedMemberIsAnErrorNotTheLastValue) {
  const std::string twice = R"({"id": 1, "op": "union", "op": "intersection", "a_wkt": ")" + std::string(square_a) +
                            R"(", "b_wkt": ")" + std::string(square_b) + "\"}\n";
  const ProcessResult r = run_mkbool({"batch", "-"}, twice + case_line(2, "union", square_a, square_b));
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  ASSERT_TRUE(lines[0].contains("error")) << lines[0];
  EXPECT_NE(lines[0]["error"].get<std::string>().find("at op: member \"op\" is repeated"), std::string::npos) << lines[0];
  EXPECT_FALSE(lines[1].contains("error")) << lines[1];
  EXPECT_EQ(lines[1]["id"], 2);
}

TEST(cliBatch, SymdifferenceIsAnAliasOfXor) {
  const std::string input = case_line(1, "symdifference", square_a, square_b) + case_line(2, "xor", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0]["op"], "symdifference");
  EXPECT_EQ(lines[0]["result_wkt"], lines[1]["result_wkt"]);
  EXPECT_EQ(lines[0]["area_exact"], "6");
  EXPECT_EQ(
      lines[0]["result_wkt"],
      "MULTIPOLYGON (((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0)), ((2 2, 2 1, 3 1, 3 3, 1 3, 1 2, 2 2)))");
}

TEST(cliBatch, OutputLinesHaveTheDocumentedFieldsAndExactAreas) {
  // Two triangles whose intersection has the crossings (3/4, 3/4) and (1, 2/3): area 11/24.
  const std::string input =
      case_line("t", "intersection", "POLYGON((0 0,3 0,0 1,0 0))", "POLYGON((0 0,1 0,1 1,0 0))") +
      "{\"id\": [1, \"x\"], \"op\": \"difference\", \"a_wkt\": \"POLYGON((0 0,1 0,1 1,0 1,0 0))\", \"b_wkt\": "
      "\"POLYGON((0 0,1 0,1 1,0 0))\", \"note\": \"ignored\"}\n";
  for (const std::string_view kernel : kernel_names()) {
    const ProcessResult r = run_mkbool({"batch", "-", "--kernel", std::string(kernel)}, input);
    ASSERT_EQ(r.exit_code, 0) << describe(r);
    const auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 2u) << r.out;
    for (const auto& line : lines) {
      std::vector<std::string> keys;
      for (const auto& item : line.items()) keys.push_back(item.key());
      EXPECT_EQ(keys, (std::vector<std::string>{"id", "op", "kernel", "result_wkt", "area", "area_beyond_double",
                                                "area_exact", "valid", "op_ns", "snapped", "line"}))
          << line;
      EXPECT_EQ(line["kernel"], std::string(kernel));
      if (is_exact_kernel(kernel)) {
        EXPECT_EQ(line["valid"], true);
      } else {
        EXPECT_TRUE(line["valid"].is_boolean()) << line;
      }
      EXPECT_TRUE(line["op_ns"].is_number_integer());
    }
    EXPECT_EQ(lines[0]["id"], "t");
    EXPECT_EQ(lines[1]["id"], Json::parse(R"([1, "x"])"));
    if (is_exact_kernel(kernel)) {
      EXPECT_EQ(lines[0]["area_exact"], "11/24");
      EXPECT_EQ(lines[0]["area"], 11.0 / 24.0);  // the nearest double
      EXPECT_EQ(lines[1]["area_exact"], "1/2");
      EXPECT_EQ(lines[1]["area"], 0.5);
    } else {
      // Rounded kernels: recorded, not asserted beyond their shape (STYLE.md).
      EXPECT_TRUE(lines[0]["area_exact"].is_null());
      EXPECT_TRUE(lines[0]["area"].is_number());
    }
  }
}

TEST(cliBatch, NonRegularAndBlankLines) {
  const std::string input =
      std::string("\n") + case_line(1, "intersection", square_a, "POLYGON((2 0,4 0,4 2,2 2,2 0))") + "\r\n";
  const ProcessResult r = run_mkbool({"batch", "-", "--non-regular"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  EXPECT_EQ(lines[0]["line"], 2);
  EXPECT_EQ(lines[0]["result_wkt"], "GEOMETRYCOLLECTION (LINESTRING (2 0, 2 2))");
  EXPECT_EQ(lines[0]["area_exact"], "0");
}

TEST(cliBatch, FileInputAndAtomicOutput) {
  TempDir dir;
  const std::string in = dir.write("cases.jsonl", case_line(1, "union", square_a, square_b));
  const std::string out = dir.file("results.jsonl");
  const ProcessResult r = run_mkbool({"batch", in, "-o", out});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(parse_lines(read_text(out)).at(0)["area_exact"], "7");
  const ProcessResult missing = run_mkbool({"batch", dir.file("none.jsonl"), "-o", dir.file("x.jsonl")});
  EXPECT_EQ(missing.exit_code, 3) << describe(missing);
  EXPECT_NE(missing.err.find("cannot open"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.jsonl")));
  const ProcessResult directory = run_mkbool({"batch", dir.path().string()});
  EXPECT_EQ(directory.exit_code, 3) << describe(directory);
  EXPECT_NE(directory.err.find("is a directory"), std::string::npos);
}

TEST(cliBatch, MillionLevelNestingNeverStopsTheBatch) {
  // issue 10, item 2: 100,000 nested arrays in an ignored member overflowed the stack while
  // the line was parsed (ordered_json copies its values when an object grows). Each deep
  // line sits between good ones: ignored members of any depth are fine, an id deeper than
  // 1000 levels or a deep value where a string belongs is that line's error, an unclosed
  // one is malformed JSON.
  constexpr std::size_t n = 1'000'000;
  const std::string arrays = std::string(n, '[') + std::string(n, ']');
  const std::string objects = [&] {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += "{\"a\":";
    return s + "1" + std::string(n, '}');
  }();
  const std::string rest = "\"op\":\"union\",\"a_wkt\":\"" + square_a + "\",\"b_wkt\":\"" + square_b + "\"";
  const std::string input = "{\"x\":" + arrays + ",\"id\":1," + rest + ",\"y\":" + objects + "}\n" +  //
                            "{\"id\":" + arrays + "," + rest + "}\n" +                                     //
                            "{\"id\":3,\"op\":" + objects + ",\"a_wkt\":\"" + square_a + "\"}\n" +     //
                            std::string(n, '[') + "\n" +                                                    //
                            "{\"id\":5,\"op\":\"union\",\"a_wkt\":" + arrays + "," + rest.substr(rest.find("\"b_wkt")) + "}\n" +
                            "{\"id\":" + std::string(1000, '[') + std::string(1000, ']') + "," + rest + "}\n" +
                            case_line(7, "union", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 7u) << r.out.substr(0, 2000);
  const char* errors[] = {nullptr, "\"id\" nests deeper than 1000 levels", "\"op\" is not a string",
                          "malformed JSON", "\"a_wkt\" is not a string", nullptr, nullptr};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(lines[i]["line"], i + 1);
    if (errors[i] == nullptr) {
      EXPECT_FALSE(lines[i].contains("error")) << lines[i].dump().substr(0, 300);
      EXPECT_EQ(lines[i]["area_exact"], "7");
    } else {
      ASSERT_TRUE(lines[i].contains("error")) << lines[i].dump().substr(0, 300);
      EXPECT_NE(lines[i]["error"].get<std::string>().find(errors[i]), std::string::npos) << lines[i]["error"];
    }
  }
  EXPECT_EQ(lines[0]["id"], 1);
  EXPECT_EQ(lines[6]["id"], 7);
  // The 1000-level id is echoed whole.
  EXPECT_EQ(lines[5]["id"].dump(), std::string(1000, '[') + std::string(1000, ']'));
}

TEST(cliBatch, MultiPartCasesAreCheckedAsTheCommandChecksThem) {
  // issue 10, item 4: the same square twice intersected to EMPTY; now that line is refused
  // by name and the lines around it are answered.
  const std::string twice = "MULTIPOLYGON(((0 0,10 0,10 10,0 10,0 0)),((0 0,10 0,10 10,0 10,0 0)))";
  const std::string input = case_line(1, "union", square_a, square_b) + case_line(2, "intersection", twice, twice) +
                            case_line(3, "union", square_a, "POLYGON((0 0,1 0,1 1,0 0),(5 5,6 5,6 6,5 5))") +
                            case_line(4, "union", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[0]["area_exact"], "7");
  EXPECT_EQ(lines[1]["error"], "a_wkt: polygon 1 repeats polygon 0 (their shells are the same ring); the parts of a "
                               "multi-part polygon must not overlap (read by nesting, the overlap would become a hole: "
                               "merge the parts first)");
  EXPECT_NE(lines[2]["error"].get<std::string>().find("b_wkt: polygon 0, ring 1 (a hole) lies outside its shell"),
            std::string::npos)
      << lines[2];
  EXPECT_EQ(lines[3]["area_exact"], "7");
}

TEST(cliBatch, InvalidUtf8IsThatLinesErrorAndTheOutputStaysUtf8) {
  const std::string input = "{\"id\":\"\xff\xfe\",\"op\":\"union\"}\n" + case_line(2, "union", square_a, square_b);
  const ProcessResult r = run_mkbool({"batch", "-"}, input);
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);  // nlohmann refuses invalid UTF-8: the output has none
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0]["error"].get<std::string>().find("ill-formed UTF-8"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1]["area_exact"], "7");
}

TEST(cliBatch, EmptyBatchWritesNothing) {
  const ProcessResult r = run_mkbool({"batch", "-"}, "");
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "");
}

// Exact in, exact out (issue 12): a line's "result" (asked with "exact_result" or
// --exact-result) is a native JSON polygon with exact coordinates, taken back as "a" or "b".
// Hand-derived: A ∩ B below is the quadrilateral (0 0, 1 0, 1 2/3, 3/4 3/4) of area 11/24;
// inside the square [0, 1/3]² only y <= x binds (A's edge y = 1 - x/3 stays above 1/3), so
// (A ∩ B) ∩ C is the triangle (0 0, 1/3 0, 1/3 1/3) of area 1/18, and (A ∩ B) ∪ C has area
// 11/24 + 1/9 - 1/18 = 37/72.
TEST(cliBatch, ExactResultsAreFedBackExactlyInEveryExactKernel) {
  const std::string first = Json{{"id", 1}, {"op", "intersection"}, {"a_wkt", "POLYGON((0 0,3 0,0 1,0 0))"},
                                 {"b_wkt", "POLYGON((0 0,1 0,1 1,0 0))"}, {"exact_result", true}}.dump() + "\n";
  const ProcessResult r1 = run_mkbool({"batch", "-"}, first);
  ASSERT_EQ(r1.exit_code, 0) << describe(r1);
  const auto lines1 = parse_lines(r1.out);
  ASSERT_EQ(lines1.size(), 1u);
  const Json ab = lines1[0]["result"];
  ASSERT_TRUE(ab.is_object()) << lines1[0];
  EXPECT_NE(ab.dump().find("\"2/3\""), std::string::npos) << ab;  // the crossing (1, 2/3), exactly
  const Json c = Json::parse(R"({"type": "island", "rings": [[["0", "0"], ["1/3", "0"], ["1/3", "1/3"], ["0", "1/3"]]]})");
  for (const std::string_view kernel : kernel_names()) {
    std::string input;
    input += Json{{"id", "and"}, {"op", "intersection"}, {"a", ab}, {"b", c}}.dump() + "\n";
    input += Json{{"id", "or"}, {"op", "union"}, {"a", ab}, {"b", c}}.dump() + "\n";
    const ProcessResult r = run_mkbool({"batch", "-", "--kernel", std::string(kernel), "--exact-result"}, input);
    ASSERT_EQ(r.exit_code, 0) << describe(r);
    const auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 2u) << r.out;
    if (!is_exact_kernel(kernel)) {
      // 1/3 is not a double: the rounded kernels refuse by name.
      for (const auto& line : lines) EXPECT_NE(line["error"].get<std::string>().find("takes doubles only"), std::string::npos) << line;
      continue;
    }
    EXPECT_EQ(lines[0]["area_exact"], "1/18") << kernel << ": " << lines[0];
    EXPECT_EQ(lines[1]["area_exact"], "37/72") << kernel << ": " << lines[1];
    EXPECT_NE(lines[0]["result"].dump().find("\"1/3\""), std::string::npos) << lines[0];
    EXPECT_EQ(lines[0]["result_wkt"], "POLYGON ((0 0, 0.3333333333333333 0, 0.3333333333333333 0.3333333333333333, 0 0))");
  }
}

TEST(cliBatch, NativePolygonsAreCheckedAndNotMixedWithWkt) {
  const std::string bad_type = R"j({"op":"union","a":[[0,0]],"b":{"rings":[[[0,0],[1,0],[0,1]]]}})j";
  const std::string mixed = R"j({"op":"union","a":{"rings":[[[0,0],[1,0],[0,1]]]},"b_wkt":"POLYGON((0 0,1 0,0 1,0 0))"})j";
  const std::string bad_number = R"j({"op":"union","a":{"rings":[[[0,0],["1/0",0],[0,1]]]},"b":{"rings":[[[0,0],[1,0],[0,1]]]}})j";
  const std::string unbounded = R"j({"op":"union","a":{"type":"hole","rings":[[[0,0],[1,0],[0,1]]]},"b":{"rings":[[[5,5],[6,5],[5,6]]]}})j";
  const ProcessResult r = run_mkbool({"batch", "-"}, bad_type + "\n" + mixed + "\n" + bad_number + "\n" + unbounded + "\n");
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto lines = parse_lines(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_NE(lines[0]["error"].get<std::string>().find("\"a\" is not a native JSON polygon object"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1]["error"].get<std::string>().find("not both"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2]["error"].get<std::string>().find("a: native JSON at rings[0][1][0]"), std::string::npos) << lines[2];
  EXPECT_NE(lines[3]["error"].get<std::string>().find("unbounded"), std::string::npos) << lines[3];
  // The unbounded result has no WKT, but its native form is written when asked for.
  std::string asked = unbounded;
  asked.insert(asked.size() - 1, ",\"exact_result\":true");
  const ProcessResult r2 = run_mkbool({"batch", "-"}, asked + "\n");
  const auto lines2 = parse_lines(r2.out);
  ASSERT_EQ(lines2.size(), 1u) << r2.out;
  EXPECT_FALSE(lines2[0].contains("error")) << lines2[0];
  EXPECT_TRUE(lines2[0]["result_wkt"].is_null());
  EXPECT_EQ(lines2[0]["result"]["unbounded"], true);
}

}  // namespace
}  // namespace mk::test
