// Tests of the native JSON format: island/hole types, degenerate rings, exact rational
// coordinates (accepted only when they are doubles), errors, and both writers.
// [MK89 §2.2] [MK89 §3.1 step 6]
// Preconditions: none.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "io/native_json.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

using test::rejects;

TEST(ioNativeJson, ReadsIslandAndHole) {
  const Polygon p = read_native_json(R"({"type": "hole", "rings": [[[0,0],[4,0],[4,4],[0,4]]]})");
  EXPECT_EQ(p.type, PolygonType::hole);
  ASSERT_EQ(p.rings.size(), 1u);
  EXPECT_EQ(p.rings[0], (Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  EXPECT_EQ(read_native_json(R"({"type": "island", "rings": []})").type, PolygonType::island);
  EXPECT_EQ(read_native_json(R"({"rings": []})").type, PolygonType::island);
}

TEST(ioNativeJson, AcceptsOneAndTwoSidedRings) {
  const Polygon p = read_native_json(R"({"rings": [[[1,2]], [[0,0],[3,0]], [[5,5],[5,5]]]})");
  ASSERT_EQ(p.rings.size(), 3u);
  EXPECT_EQ(p.rings[0], (Ring{{1, 2}}));
  EXPECT_EQ(p.rings[1], (Ring{{0, 0}, {3, 0}}));
  EXPECT_EQ(p.rings[2], (Ring{{5, 5}}));
}

TEST(ioNativeJson, RemovesClosingAndRepeatedVertices) {
  const Polygon p = read_native_json(R"({"rings": [[[0,0],[4,0],[4,0],[4,4],[0,4],[0,0]]]})");
  EXPECT_EQ(p.rings[0], (Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
}

TEST(ioNativeJson, ReadsExactRationalStrings) {
  const Polygon p = read_native_json(
      R"({"rings": [[["1/2", "-3"], ["+5", "6/4"], ["0/7", "9007199254740992"]]]})");
  EXPECT_EQ(p.rings[0], (Ring{{0.5, -3}, {5, 1.5}, {0, 9007199254740992.0}}));
}

TEST(ioNativeJson, ReadsExtremeDoublesGivenExactly) {
  // The largest double and the smallest subnormal, written as exact integers / rationals.
  mpz_class max_int;
  mpz_ui_pow_ui(max_int.get_mpz_t(), 2, 1024);
  mpz_class ulp;
  mpz_ui_pow_ui(ulp.get_mpz_t(), 2, 971);
  max_int -= ulp;  // (2 - 2^-52) * 2^1023
  mpz_class two_1074;
  mpz_ui_pow_ui(two_1074.get_mpz_t(), 2, 1074);
  const std::string text = R"({"rings": [[[")" + max_int.get_str() + R"(", "1/)" +
                           two_1074.get_str() + R"("]]]})";
  const Polygon p = read_native_json(text);
  EXPECT_EQ(p.rings[0][0].x, std::numeric_limits<double>::max());
  EXPECT_EQ(p.rings[0][0].y, std::numeric_limits<double>::denorm_min());
}

TEST(ioNativeJson, RejectsRationalsThatAreNotDoubles) {
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[["1/3", 0]]]})"); },
                      "native JSON at rings[0][0][0]: coordinate \"1/3\" is not exactly a double; "
                      "only doubles are supported as input coordinates"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[0, "9007199254740993"]]]})"); },
                      "native JSON at rings[0][0][1]: coordinate \"9007199254740993\" is not "
                      "exactly a double"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[0, 0], [9007199254740993, 0]]]})"); },
                      "native JSON at rings[0][1][0]: integer coordinate 9007199254740993 is not "
                      "exactly a double; only doubles are supported as input coordinates"));
  mpz_class huge;
  mpz_ui_pow_ui(huge.get_mpz_t(), 2, 1024);
  EXPECT_TRUE(rejects([&] { read_native_json(R"({"rings": [[[")" + huge.get_str() + R"(", 0]]]})"); },
                      "is not exactly a double"));
  mpz_class tiny;
  mpz_ui_pow_ui(tiny.get_mpz_t(), 2, 1075);
  EXPECT_TRUE(rejects([&] { read_native_json(R"({"rings": [[["1/)" + tiny.get_str() + R"(", 0]]]})"); },
                      "is not exactly a double"));
}

TEST(ioNativeJson, RejectsMalformedCoordinates) {
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[["0.5", 0]]]})"); },
                      "native JSON at rings[0][0][0]: coordinate \"0.5\" is not a number: expected "
                      "a JSON number, an integer \"p\" or a rational \"p/q\""));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[["1/0", 0]]]})"); },
                      "native JSON at rings[0][0][0]: coordinate \"1/0\" has a zero denominator"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[["", 0]]]})"); }, "is not a number"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[" 1", 0]]]})"); }, "is not a number"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[true, 0]]]})"); },
                      "native JSON at rings[0][0][0]: expected a number, found a boolean or a "
                      "rational string \"p/q\""));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[0, 1e999]]]})"); },
                      "native JSON: number overflow parsing '1e999'"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[0, 0], [1e-999, 0], [0, 1]]]})"); },
                      "native JSON at rings[0][1][0]: coordinate is not representable as a double (not zero"));
}

TEST(ioNativeJson, RejectsBadStructure) {
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[]]})"); },
                      "native JSON at rings[0]: ring is empty; a ring needs at least 1 point"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [[[0, 0, 0]]]})"); },
                      "native JSON at rings[0][0]: point has 3 coordinates; expected exactly 2"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"type": "island"})"); },
                      "native JSON at top level: missing \"rings\" member"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"type": "Polygon", "rings": []})"); },
                      "native JSON at type: expected \"island\" or \"hole\", found \"Polygon\""));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": [], "ring": []})"); },
                      "native JSON at top level: unknown member \"ring\"; expected \"type\" and "
                      "\"rings\""));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"rings": {}})"); },
                      "native JSON at rings: expected an array of rings, found an object"));
  EXPECT_TRUE(rejects([] { read_native_json("[]"); }, "native JSON at top level: expected an object"));
  EXPECT_TRUE(rejects([] { read_native_json("{\n\"rings\": [[[0, 0]]\n"); },
                      "native JSON line 3, column 1: syntax error"));
  EXPECT_TRUE(rejects([] { read_native_json(""); }, "native JSON line 1, column 1: empty input"));
}

TEST(ioNativeJson, DeepNestingFailsWithoutRecursion) {
  const std::string deep =
      R"({"rings":)" + std::string(100000, '[') + std::string(100000, ']') + "}";
  EXPECT_TRUE(rejects([&] { read_native_json(deep); },
                      "native JSON at rings[0][0]: point has 1 coordinates"));
}

TEST(ioNativeJson, PolygonWriterRoundTrips) {
  const Polygon p{{{{0.1, -2.5e-310}, {4, 0}, {4, 4}}, {{7, 7}}, {{1, 1}, {2, 2}}},
                  PolygonType::hole};
  const std::string text = write_native_json(p);
  const Polygon back = read_native_json(text);
  EXPECT_EQ(back.type, PolygonType::hole);
  EXPECT_EQ(back.rings, p.rings);
  EXPECT_EQ(read_native_json(write_native_json(Polygon{})).rings.size(), 0u);
}

TEST(ioNativeJson, OutputWriterCarriesTypesExactValuesAndNonRegularParts) {
  Output out;
  out.irreducible.push_back({{{0, 0}, {1, 0}, {0, 1}}, {"0", "0", "1", "0", "0", "1"}, PolygonType::island});
  out.irreducible.push_back({{{0.25, 0.25}, {0.5, 0.25}, {0.25, 0.5}}, {}, PolygonType::hole});
  out.dangling_edges = {{{1, 0}, {2, 0}}};
  out.isolated_points = {{5, 5}};
  out.rounded_valid = true;
  const nlohmann::json j = nlohmann::json::parse(write_native_json(out, "exact \"kernel\""));
  EXPECT_EQ(j["kernel"], "exact \"kernel\"");
  EXPECT_EQ(j["unbounded"], false);
  EXPECT_EQ(j["rounded_valid"], true);
  ASSERT_EQ(j["polygons"].size(), 2u);
  EXPECT_EQ(j["polygons"][0]["type"], "island");
  EXPECT_EQ(j["polygons"][0]["vertices"], nlohmann::json::parse("[[0,0],[1,0],[0,1]]"));
  EXPECT_EQ(j["polygons"][0]["exact"], nlohmann::json::parse(R"([["0","0"],["1","0"],["0","1"]])"));
  EXPECT_EQ(j["polygons"][1]["type"], "hole");
  EXPECT_FALSE(j["polygons"][1].contains("exact"));
  EXPECT_EQ(j["dangling_edges"], nlohmann::json::parse("[[[1,0],[2,0]]]"));
  EXPECT_EQ(j["isolated_points"], nlohmann::json::parse("[[5,5]]"));
}

// Every member of native JSON is read, so any name given twice in one object is refused,
// with its path. [RFC8259 §4]
TEST(ioNativeJson, RepeatedMembersAreRefusedWithTheirPath) {
  EXPECT_TRUE(rejects([] { read_native_json(R"({"type":"island","rings":[[[0,0],[1,0],[1,1]]],"rings":[]})"); },
                      "native JSON at rings: member \"rings\" is repeated"));
  EXPECT_TRUE(rejects([] { read_native_json(R"({"type":"island","type":"hole","rings":[[[0,0],[1,0],[1,1]]]})"); },
                      "native JSON at type: member \"type\" is repeated"));
}

TEST(ioNativeJson, OutputWriterForEmptyAndUnboundedResults) {
  Output out;
  nlohmann::json j = nlohmann::json::parse(write_native_json(out, "double"));
  EXPECT_TRUE(j["rounded_valid"].is_null());
  EXPECT_TRUE(j["polygons"].empty());
  out.unbounded = true;
  out.rounded_valid = false;
  out.irreducible.push_back({{{0, 0}, {0, 1}, {1, 0}}, {}, PolygonType::hole});
  j = nlohmann::json::parse(write_native_json(out, "rational"));
  EXPECT_EQ(j["unbounded"], true);
  EXPECT_EQ(j["rounded_valid"], false);
  EXPECT_EQ(j["polygons"][0]["type"], "hole");
}

// A non-regular result read back as an operand: every cycle is a ring, dangling edges rings
// of 2 vertices and isolated points rings of 1, with their exact coordinates; an unbounded
// result with such parts is refused by name.
TEST(ioNativeJson, NonRegularResultsReadBackWithTheirDegenerateParts) {
  Output out;
  out.irreducible.push_back({{{0, 0}, {1, 0}, {0, 1}}, {"0", "0", "1", "0", "0", "1"}, PolygonType::island});
  out.irreducible.push_back({{{1, 0}, {2, 0}}, {"1", "0", "2", "0"}, PolygonType::island});
  out.irreducible.push_back({{{0.3333333333333333, 5}}, {"1/3", "5"}, PolygonType::island});
  out.dangling_edges = {{{1, 0}, {2, 0}}};
  out.isolated_points = {{0.3333333333333333, 5}};
  const ExactPolygon p = read_native_json_exact(write_native_json(out, "exact"));
  EXPECT_EQ(p.type, PolygonType::island);
  ASSERT_EQ(p.rings.size(), 3u);
  EXPECT_EQ(p.rings[0].size(), 3u);
  ASSERT_EQ(p.rings[1].size(), 2u);
  EXPECT_EQ(p.rings[1][1].x, mpq_class(2));
  ASSERT_EQ(p.rings[2].size(), 1u);
  EXPECT_EQ(p.rings[2][0].x, mpq_class(1, 3));
  out.unbounded = true;
  try {
    (void)read_native_json_exact(write_native_json(out, "exact"));
    FAIL() << "an unbounded result with a dangling edge was read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("polygons[1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unbounded result with dangling edges"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mk
