// Tests of the WKT reader: accepted forms, normalisation of rings, and every rejection with
// its line, column and polygon / ring / vertex indices. [OGC06-103 §7]
// Preconditions: none.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "io/wkt.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

using test::rejects;

Ring square() { return {{0, 0}, {4, 0}, {4, 4}, {0, 4}}; }

TEST(ioWktReader, ReadsPolygonAndDropsClosingVertex) {
  const MultiPolygon mp = read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  ASSERT_EQ(mp.size(), 1u);
  EXPECT_EQ(mp[0].shell, square());
  EXPECT_TRUE(mp[0].holes.empty());
}

TEST(ioWktReader, ReadsHoles) {
  const MultiPolygon mp =
      read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))");
  ASSERT_EQ(mp.size(), 1u);
  ASSERT_EQ(mp[0].holes.size(), 1u);
  EXPECT_EQ(mp[0].holes[0], (Ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
}

TEST(ioWktReader, ReadsMultiPolygonWithEmptyMember) {
  const MultiPolygon mp = read_wkt(
      "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), EMPTY, ((10 10, 11 10, 10 11, 10 10)))");
  ASSERT_EQ(mp.size(), 2u);
  EXPECT_EQ(mp[1].shell, (Ring{{10, 10}, {11, 10}, {10, 11}}));
}

TEST(ioWktReader, ReadsGeometryCollectionOfPolygons) {
  const MultiPolygon mp = read_wkt(
      "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)), POLYGON EMPTY, "
      "MULTIPOLYGON (((5 5, 6 5, 5 6, 5 5)), ((7 7, 8 7, 7 8, 7 7))))");
  EXPECT_EQ(mp.size(), 3u);
}

TEST(ioWktReader, EmptyFormsGiveNoPolygons) {
  EXPECT_TRUE(read_wkt("POLYGON EMPTY").empty());
  EXPECT_TRUE(read_wkt("MULTIPOLYGON EMPTY").empty());
  EXPECT_TRUE(read_wkt("GEOMETRYCOLLECTION EMPTY").empty());
  EXPECT_TRUE(read_wkt("  geometrycollection ( polygon empty )  \n").empty());
}

TEST(ioWktReader, KeywordsAreCaseInsensitiveAndSpacingIsFree) {
  EXPECT_EQ(read_wkt("polygon((0 0,4 0,4 4,0 4,0 0))")[0].shell, square());
  EXPECT_EQ(read_wkt("Polygon\n(\t(0 0 ,4 0,\r\n4 4 , 0 4,0 0 ) )")[0].shell, square());
  EXPECT_EQ(read_wkt("\xEF\xBB\xBFPOLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")[0].shell, square());
}

TEST(ioWktReader, ReadsEveryDoubleSyntax) {
  const MultiPolygon mp = read_wkt(
      "POLYGON ((-0.5 .5, 5. +1, 1E3 1e-3, 4.9e-324 1.7976931348623157e308, -0.5 .5))");
  const Ring& r = mp[0].shell;
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], (Point{-0.5, 0.5}));
  EXPECT_EQ(r[1], (Point{5, 1}));
  EXPECT_EQ(r[2], (Point{1000, 0.001}));
  EXPECT_EQ(r[3].x, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(r[3].y, std::numeric_limits<double>::max());
}

TEST(ioWktReader, RemovesRepeatedConsecutiveVertices) {
  EXPECT_EQ(read_wkt("POLYGON ((0 0, 0 0, 4 0, 4 0, 4 0, 4 4, 0 4, 0 4, 0 0))")[0].shell,
            square());
  // A repeated closing vertex: the duplicate before the close goes with the close.
  EXPECT_EQ(read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0, 0 0))")[0].shell, square());
  EXPECT_EQ(read_wkt("POLYGON ((0 0, 0 0, 4 0, 4 4, 0 4, 0 0))")[0].shell, square());
}

TEST(ioWktReader, RejectsNonFiniteLiterals) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, nan 0, 1 1, 0 0))"); },
                      "WKT line 1, column 16 (polygon 0, ring 0, vertex 1): x coordinate 'nan' "
                      "is not a finite number; NaN and infinity are not allowed"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 -inf, 1 1, 0 0))"); },
                      "WKT line 1, column 18 (polygon 0, ring 0, vertex 1): y coordinate '-inf'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0, Infinity 1, 0 0))"); },
                      "(polygon 0, ring 0, vertex 2): x coordinate 'Infinity' is not a finite"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0, NaN(123) 1, 0 0))"); },
                      "x coordinate 'NaN' is not a finite number"));
}

TEST(ioWktReader, RejectsNumbersOutsideDouble) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1e400 0, 1 1, 0 0))"); },
                      "WKT line 1, column 16 (polygon 0, ring 0, vertex 1): x coordinate '1e400' "
                      "is not representable as a double"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 1e-400, 1 1, 0 0))"); },
                      "y coordinate '1e-400' is not representable as a double"));
}

TEST(ioWktReader, RejectsMalformedNumbers) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1..2 0, 1 1, 0 0))"); },
                      "WKT line 1, column 16 (polygon 0, ring 0, vertex 1): malformed number '1..2'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 0x10 0, 1 1, 0 0))"); },
                      "malformed number '0x10'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1-2 0, 1 1, 0 0))"); },
                      "malformed number '1-2'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1e 0, 1 1, 0 0))"); },
                      "malformed number '1e'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1,0, 1 1, 0 0))"); },
                      "column 17 (polygon 0, ring 0, vertex 1): expected a number (the y "
                      "coordinate), found ','"));
}

TEST(ioWktReader, RejectsUnclosedRingAtItsLastVertex) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 1))"); },
                      "WKT line 1, column 26 (polygon 0, ring 0, vertex 3): ring is not closed: "
                      "last vertex (0 1) differs from first vertex (0 0)"));
}

TEST(ioWktReader, RejectsRingsWithTooFewPoints) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0, 0 0))"); },
                      "WKT line 1, column 10 (polygon 0, ring 0): ring has 3 coordinates; a "
                      "closed ring needs at least 4 (3 distinct points and the closing point)"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0, 0 0, 1 0, 0 0))"); },
                      "WKT line 1, column 10 (polygon 0, ring 0): ring has fewer than 3 distinct "
                      "points"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 0 0, 0 0, 0 0))"); },
                      "ring has fewer than 3 distinct points"));
}

TEST(ioWktReader, NamesPolygonAndRingInMultiPolygons) {
  EXPECT_TRUE(rejects(
      [] {
        read_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)),\n"
                 "  ((0 0, 4 0, 4 4, 0 0), (1 1, 2 1, 1 1)))");
      },
      "WKT line 2, column 26 (polygon 1, ring 1): ring has 3 coordinates"));
  EXPECT_TRUE(rejects(
      [] {
        read_wkt("GEOMETRYCOLLECTION (POLYGON EMPTY,\n"
                 "POLYGON ((0 0, 4 0, 4 4, 0 0)),\n"
                 "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)), ((0 0, 4 0, inf 4, 0 0))))");
      },
      "WKT line 3, column 51 (polygon 3, ring 0, vertex 2): x coordinate 'inf'"));
}

TEST(ioWktReader, RejectsTrailingGarbage) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON EMPTY x"); },
                      "WKT line 1, column 15: unexpected text after the end of the geometry: 'x'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0)))"); },
                      "column 31: unexpected text after the end of the geometry: ')'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0));\n"); },
                      "column 31: unexpected text after the end of the geometry: ';'"));
}

TEST(ioWktReader, RejectsTruncatedText) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON"); },
                      "WKT line 1, column 8: unexpected end of input; expected '(' or EMPTY after "
                      "POLYGON"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1"); },
                      "WKT line 1, column 17 (polygon 0, ring 0, vertex 1): unexpected end of "
                      "input; expected a number (the y coordinate)"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0)"); },
                      "WKT line 1, column 30 (polygon 0): unexpected end of input; expected ',' "
                      "or ')' after a ring"));
  EXPECT_TRUE(rejects([] { read_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0))"); },
                      "unexpected end of input; expected ',' or ')' after a polygon of the "
                      "MULTIPOLYGON"));
  EXPECT_TRUE(rejects([] { read_wkt("GEOMETRYCOLLECTION (POLYGON EMPTY,"); },
                      "unexpected end of input; expected a geometry type"));
}

TEST(ioWktReader, RejectsEmptyInput) {
  EXPECT_TRUE(rejects([] { read_wkt(""); },
                      "WKT line 1, column 1: empty input: expected a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_wkt(" \n\t "); }, "WKT line 2, column 3: empty input"));
}

TEST(ioWktReader, RejectsUnknownAndNonPolygonalTypes) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGOON ((0 0, 1 0, 0 1, 0 0))"); },
                      "WKT line 1, column 1: unknown geometry type 'POLYGOON'"));
  EXPECT_TRUE(rejects([] { read_wkt("LINESTRING (0 0, 1 1)"); },
                      "WKT line 1, column 1: LINESTRING is not a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_wkt("point (1 2)"); }, "POINT is not a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_wkt("GEOMETRYCOLLECTION (POLYGON EMPTY, MULTILINESTRING EMPTY)"); },
                      "WKT line 1, column 36: MULTILINESTRING is not a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_wkt("TRIANGLE ((0 0, 1 0, 0 1, 0 0))"); },
                      "TRIANGLE is not supported; use POLYGON or MULTIPOLYGON"));
  EXPECT_TRUE(rejects([] { read_wkt("42"); },
                      "WKT line 1, column 1: expected a geometry type such as POLYGON or "
                      "MULTIPOLYGON, found '42'"));
}

TEST(ioWktReader, RejectsNestedGeometryCollection) {
  EXPECT_TRUE(rejects([] { read_wkt("GEOMETRYCOLLECTION (GEOMETRYCOLLECTION EMPTY)"); },
                      "WKT line 1, column 21: nested GEOMETRYCOLLECTION is not supported"));
}

TEST(ioWktReader, ReadsZAndMAndDropsThem) {
  // issue 10, item 5: Z and M are common in the wild; the operation is planar.
  const Ring triangle{{0, 0}, {1, 0}, {0, 1}};
  for (const char* text : {"POLYGON Z ((0 0 5, 1 0 6, 0 1 7, 0 0 5))", "POLYGONZ ((0 0 5, 1 0 6, 0 1 7, 0 0 5))",
                           "polygon m ((0 0 5, 1 0 6, 0 1 7, 0 0 5))", "POLYGON ((0 0 5, 1 0 6, 0 1 7, 0 0 5))",
                           "POLYGON ZM ((0 0 5 1, 1 0 6 1, 0 1 7 1, 0 0 5 1))",
                           "POLYGON ((0 0 5 1, 1 0 6 1, 0 1 7 1, 0 0 5 1))",
                           "MULTIPOLYGON Z (((0 0 -1e300, 1 0 0, 0 1 0, 0 0 1)))",
                           "GEOMETRYCOLLECTION Z (POLYGON Z ((0 0 5, 1 0 6, 0 1 7, 0 0 5)), POLYGON EMPTY)"}) {
    SCOPED_TRACE(text);
    const MultiPolygon mp = read_wkt(text);
    ASSERT_EQ(mp.size(), 1u);
    EXPECT_EQ(mp[0].shell, triangle);
  }
  EXPECT_TRUE(read_wkt("polygon zm EMPTY").empty());
  EXPECT_TRUE(read_wkt("MULTIPOLYGON M EMPTY").empty());
  // The closing vertex is compared in x and y only.
  EXPECT_EQ(read_wkt("POLYGON Z ((0 0 1, 1 0 1, 0 1 1, 0 0 2))")[0].shell, triangle);
}

TEST(ioWktReader, RejectsInconsistentOrBadExtraCoordinates) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON Z ((0 0, 1 0, 0 1, 0 0))"); },
                      "WKT line 1, column 13 (polygon 0, ring 0, vertex 0): vertex has 2 coordinates, but this "
                      "input's vertices have 3"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0 0, 1 0, 0 1 0, 0 0 0))"); },
                      "(polygon 0, ring 0, vertex 1): vertex has 2 coordinates, but this input's vertices have 3"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0, 1 0 0, 0 1, 0 0))"); },
                      "vertex has 3 coordinates, but the vertices before have 2"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ZM ((0 0 0, 1 0 0, 0 1 0, 0 0 0))"); }, "vertex has 3 coordinates"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON ((0 0 0 0 0, 1 0 0 0 0, 0 1 0 0 0, 0 0 0 0 0))"); },
                      "vertex has more than 4 coordinates"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON Z ((0 0 nan, 1 0 0, 0 1 0, 0 0 0))"); },
                      "third coordinate 'nan' is not a finite number"));
  EXPECT_TRUE(rejects([] { read_wkt("GEOMETRYCOLLECTION (POLYGON Z EMPTY, POLYGON M EMPTY, POLYGON ZM EMPTY)"); },
                      "POLYGON ZM has 4 coordinates per vertex, but the vertices before have 3"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON Z Z ((0 0 0, 1 0 0, 0 1 0, 0 0 0))"); }, "'(' or EMPTY"));
}

TEST(ioWktReader, RejectsEmptyShellIgnoresEmptyHole) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON (EMPTY)"); },
                      "WKT line 1, column 10 (polygon 0, ring 0): a shell ring cannot be EMPTY"));
  // GEOS's suites write empty holes (issue-geos-234); they add nothing.
  const MultiPolygon mp = read_wkt("MULTIPOLYGON (((1 1, 1 5, 5 5, 5 1, 1 1), EMPTY))");
  ASSERT_EQ(mp.size(), 1u);
  EXPECT_EQ(mp[0].shell.size(), 4u);
  EXPECT_TRUE(mp[0].holes.empty());
}

TEST(ioWktReader, RejectsMissingParenthesis) {
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON (0 0, 1 0, 0 1, 0 0)"); },
                      "WKT line 1, column 10 (polygon 0, ring 0): expected '(' to start a ring, "
                      "found '0'"));
  EXPECT_TRUE(rejects([] { read_wkt("POLYGON foo"); },
                      "expected '(' or EMPTY after POLYGON, found 'foo'"));
}

TEST(ioWktReader, MessagesQuoteAtMostAShortExcerpt) {
  const std::string long_token(100000, '7');
  const std::string text = "POLYGON ((0 0, " + long_token + "x 0, 1 1, 0 0))";
  try {
    read_wkt(text);
    FAIL() << "accepted";
  } catch (const InvalidInput& e) {
    EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
    EXPECT_NE(std::string(e.what()).find("malformed number '7777"), std::string::npos);
  }
}

TEST(ioWktReader, DeepParenthesesFailWithoutRecursion) {
  const std::string text = "POLYGON " + std::string(1000000, '(');
  EXPECT_TRUE(rejects([&] { read_wkt(text); }, "expected a number (the x coordinate), found '('"));
}

}  // namespace
}  // namespace mk
