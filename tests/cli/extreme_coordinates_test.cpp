// The command on coordinates at the ends of the double range (issue 10, item 1): an area
// beyond the largest double is reported as null with "area_beyond_double": true (never a
// crash), every output format stays finite and exact, batch answers every line around such a
// case, and negative zero is never printed.
// [MK89 §3.2] (polygonoperation) [IEEE754 §4.3.1] (overflow to infinity) [RFC8259 §6] (no inf)
// Preconditions: the built mkbool (MK_CLI_EXE).
#include <gtest/gtest.h>
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

const std::string big_square = "POLYGON((0 0,1e200 0,1e200 1e200,0 1e200,0 0))";
const std::string max = "1.7976931348623157e308";
const std::string min_sub = "5e-324";
// A square and a diamond spanning the whole double range, and a thin strip a subnormal high.
const std::string full_square = "POLYGON((-" + max + " -" + max + "," + max + " -" + max + "," + max + " " + max +
                                ",-" + max + " " + max + ",-" + max + " -" + max + "))";
const std::string full_diamond =
    "POLYGON((-" + max + " 0,0 -" + max + "," + max + " 0,0 " + max + ",-" + max + " 0))";
const std::string strip = "POLYGON((0 0," + max + " 0," + max + " " + min_sub + ",0 " + min_sub + ",0 0))";
const std::string tiny = "POLYGON((0 0,1.5e-323 0,1.5e-323 1e-323,0 1e-323,0 0))";
const std::string tiny_b = "POLYGON((5e-324 5e-324,2e-323 5e-324,2e-323 1.5e-323,5e-324 5e-324))";

std::string exact_big_area() {
  const mpq_class side(1e200);
  return mpq_class(side * side).get_str();
}

// No text a JSON or SVG reader would choke on, and no negative zero.
void expect_clean(const std::string& text) {
  for (const char* bad : {"nan", "NaN", "inf", "Inf", "-0 ", "-0,", "-0)", "-0]", "-0.00"}) {
    EXPECT_EQ(text.find(bad), std::string::npos) << "'" << bad << "' in\n" << text.substr(0, 3000);
  }
}

TEST(cliExtremeCoordinates, AreaBeyondTheLargestDoubleIsNullAndFlagged) {
  // The reproducer of issue 10: this died with SIGFPE (exit 136).
  const ProcessResult r = run_mkbool({"intersection", big_square, big_square, "--stats"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "POLYGON ((0 0, 1e+200 0, 1e+200 1e+200, 0 1e+200, 0 0))\n");
  ASSERT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  const auto stats = nlohmann::json::parse(r.err);
  EXPECT_TRUE(stats["area"].is_null());
  EXPECT_EQ(stats["area_beyond_double"], true);
  EXPECT_EQ(stats["area_exact"], exact_big_area());

  // The same run into a file: the file is written whole and nothing else is left behind.
  TempDir dir;
  const ProcessResult to_file = run_mkbool({"intersection", big_square, big_square, "--stats", "-o", dir.file("r.wkt")});
  ASSERT_EQ(to_file.exit_code, 0) << describe(to_file);
  EXPECT_EQ(read_text(dir.file("r.wkt")), r.out);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"r.wkt"});
}

TEST(cliExtremeCoordinates, RoundedKernelsReportTheOverflowToo) {
  for (const char* kernel : {"adaptive", "interval", "double"}) {
    const ProcessResult r = run_mkbool({"intersection", big_square, big_square, "--stats", "--kernel", kernel});
    ASSERT_EQ(r.exit_code, 0) << kernel << "\n" << describe(r);
    const auto stats = nlohmann::json::parse(r.err);
    EXPECT_TRUE(stats["area"].is_null()) << kernel;
    EXPECT_EQ(stats["area_beyond_double"], true) << kernel;
  }
}

TEST(cliExtremeCoordinates, EveryFormatStaysFiniteAtTheEndsOfTheRange) {
  struct Case {
    const std::string* a;
    const std::string* b;
  };
  for (const Case& c : {Case{&full_square, &full_diamond}, Case{&strip, &full_square}, Case{&tiny, &tiny_b},
                        Case{&strip, &tiny}}) {
    for (const char* op : {"intersection", "union", "difference", "xor"}) {
      for (const char* format : {"wkt", "geojson", "json", "svg"}) {
        SCOPED_TRACE(*c.a + " " + op + " " + *c.b + " --format " + format);
        const ProcessResult r = run_mkbool({op, *c.a, *c.b, "--format", format, "--stats"});
        ASSERT_EQ(r.exit_code, 0) << describe(r);
        expect_clean(r.out);
        const auto stats = nlohmann::json::parse(r.err);
        EXPECT_EQ(stats["rounded_valid"], true);
        EXPECT_TRUE(stats["area_exact"].is_string());
        EXPECT_EQ(stats["area"].is_null(), stats["area_beyond_double"].get<bool>()) << stats;
        if (std::string(format) == "svg") {
          // Pixel coordinates stay within the picture (780 x 814 at most).
          std::istringstream in(r.out);
          for (std::string word; in >> word;) {
            const auto quote = word.find("=\"");
            if (quote == std::string::npos) continue;
            char* end = nullptr;
            const double v = std::strtod(word.c_str() + quote + 2, &end);
            if (end != word.c_str() + quote + 2) {
              EXPECT_LE(std::abs(v), 1000.0) << word;
            }
          }
        }
      }
    }
  }
}

TEST(cliExtremeCoordinates, SubnormalCornersAreDrawnApart) {
  // Before, halving 5e-324 gave 0, and the whole picture collapsed onto one point.
  const std::string unit = "POLYGON((0 0,5e-324 0,5e-324 5e-324,0 5e-324,0 0))";
  const ProcessResult r = run_mkbool({"intersection", unit, unit, "--format", "svg"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const auto path = r.out.find("d=\"M");
  ASSERT_NE(path, std::string::npos) << r.out;
  const std::string d = r.out.substr(path, r.out.find('"', path + 3) - path);
  EXPECT_NE(d.find("M30.00 "), std::string::npos) << d;   // the left edge at the margin
  EXPECT_NE(d.find("L750.00 "), std::string::npos) << d;  // the right edge 720 pixels further
}

TEST(cliExtremeCoordinates, BatchAnswersEveryLineAroundAnOverflowingArea) {
  const auto line = [](int id, const std::string& a, const std::string& b) {
    return nlohmann::json{{"id", id}, {"op", "intersection"}, {"a_wkt", a}, {"b_wkt", b}}.dump() + "\n";
  };
  const std::string small = "POLYGON((0 0,2 0,2 2,0 2,0 0))";
  const std::string input = line(1, small, small) + line(2, big_square, big_square) + line(3, full_square, full_diamond) +
                            line(4, small, small);
  for (const char* kernel : {"exact", "rational", "adaptive"}) {
    const ProcessResult r = run_mkbool({"batch", "-", "--kernel", kernel}, input);
    ASSERT_EQ(r.exit_code, 0) << kernel << "\n" << describe(r);
    std::vector<nlohmann::json> lines;
    std::istringstream in(r.out);
    for (std::string l; std::getline(in, l);) lines.push_back(nlohmann::json::parse(l));
    ASSERT_EQ(lines.size(), 4u) << r.out;
    for (const auto& l : lines) EXPECT_FALSE(l.contains("error")) << l;
    EXPECT_EQ(lines[0]["area"], 4.0);
    EXPECT_EQ(lines[0]["area_beyond_double"], false);
    for (const std::size_t i : {1u, 2u}) {
      EXPECT_TRUE(lines[i]["area"].is_null()) << lines[i];
      EXPECT_EQ(lines[i]["area_beyond_double"], true) << lines[i];
    }
    if (std::string(kernel) != "adaptive") {
      EXPECT_EQ(lines[1]["area_exact"], exact_big_area());
    }
    EXPECT_EQ(lines[3]["area"], 4.0);
  }
}

TEST(cliExtremeCoordinates, NegativeZeroIsNeverPrinted) {
  const std::string a = "POLYGON((-0 -0,2 -0,2 2,-0 2,-0 -0))";
  const std::string b = "POLYGON((-0 -0,1 -0,-0 1,-0 -0))";
  for (const char* format : {"wkt", "geojson", "json", "svg"}) {
    for (const char* op : {"intersection", "difference", "union"}) {
      const ProcessResult r = run_mkbool({op, a, b, "--format", format, "--non-regular", "--stats"});
      ASSERT_EQ(r.exit_code, 0) << describe(r);
      expect_clean(r.out);
      expect_clean(r.err);
    }
  }
  const ProcessResult batch = run_mkbool(
      {"batch", "-"}, nlohmann::json{{"id", 1}, {"op", "intersection"}, {"a_wkt", a}, {"b_wkt", b}}.dump() + "\n");
  expect_clean(batch.out);
  EXPECT_NE(batch.out.find("POLYGON ((0 0, 1 0, 0 1, 0 0))"), std::string::npos) << batch.out;
}

}  // namespace
}  // namespace mk::test
