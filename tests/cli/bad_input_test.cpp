// The bad-input suite of issue 3, run through the command: every malformed or out-of-domain
// input ends in exit 3 and one `mkbool: error:` line naming the problem and where, under a
// time limit. [MK89 §3.3] (crossing edges cannot be repaired) [OGC06-103 §7] [RFC7946]
// Preconditions: the built mkbool (MK_CLI_EXE).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "tests/cli/canonical_wkt.hpp"
#include "tests/cli/cli_support.hpp"

namespace mk::test {
namespace {

// Exit 3, nothing on standard output, one error line containing every fragment.
void expect_invalid(const std::vector<std::string>& args, std::initializer_list<std::string> fragments,
                    const std::string& input = {}) {
  const ProcessResult r = run_mkbool(args, input);
  ASSERT_FALSE(r.timed_out) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_EQ(r.out, "") << describe(r);
  EXPECT_EQ(r.err.rfind("mkbool: error: ", 0), 0u) << describe(r);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected\n" << describe(r);
  for (const auto& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "'\n" << describe(r);
}

void expect_invalid_a(const std::string& a, std::initializer_list<std::string> fragments) {
  expect_invalid({"intersection", a, square_b}, fragments);
}

TEST(cliBadInput, NanCoordinate) {
  expect_invalid_a("POLYGON((0 0,nan 0,2 2,0 2,0 0))",
                   {"A (inline WKT)", "line 1, column 14", "ring 0, vertex 1", "'nan' is not a finite number"});
}

TEST(cliBadInput, InfiniteCoordinate) {
  expect_invalid_a("POLYGON((0 0,2 0,2 -inf,0 2,0 0))", {"vertex 2", "'-inf' is not a finite number"});
  expect_invalid_a("POLYGON((0 0,2 0,2 2,0 1e400,0 0))", {"vertex 3", "'1e400' is not representable as a double"});
}

TEST(cliBadInput, NonFiniteCoordinateInJson) {
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"Polygon","coordinates":[[[0,0],[1e400,1],[1,0],[0,0]]]})"),
                   {"A (file '", "a.geojson'", "GeoJSON", "1e400"});
  expect_invalid_a(dir.write("a.json", R"({"rings":[[[0,0],["nan",0],[1,1]]]})"),
                   {"native JSON at rings[0][1][0]", "\"nan\" is not a number"});
}

TEST(cliBadInput, WktRingWithFewerThanThreeDistinctPoints) {
  expect_invalid_a("POLYGON((0 0,1 1,0 0,0 0))", {"(polygon 0, ring 0)", "fewer than 3 distinct points"});
  expect_invalid_a("MULTIPOLYGON(((0 0,4 0,4 4,0 0)),((5 5,6 6,5 5,5 5)))", {"polygon 1, ring 0", "fewer than 3 distinct points"});
}

TEST(cliBadInput, GeoJsonRingWithFewerThanThreeDistinctPoints) {
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"Polygon","coordinates":[[[0,0],[1,1],[0,0],[0,0]]]})"),
                   {"GeoJSON at coordinates[0]", "fewer than 3 distinct points"});
}

TEST(cliBadInput, NativeJsonDegenerateRingsAreAccepted) {
  // The paper's model: one-sided (a point) and two-sided (a segment) rings are polygons.
  const ProcessResult r = run_mkbool(
      {"intersection", R"({"type":"island","rings":[[[0,0],[4,4]]]})", square_b, "--non-regular"});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(r.out, "GEOMETRYCOLLECTION (LINESTRING (1 1, 3 3))\n") << describe(r);
}

TEST(cliBadInput, UnclosedWktRing) {
  expect_invalid_a("POLYGON((0 0,2 0,2 2,0 2))", {"ring 0, vertex 3", "ring is not closed"});
}

TEST(cliBadInput, TrailingGarbage) {
  expect_invalid_a("POLYGON((0 0,2 0,2 2,0 2,0 0)) x", {"line 1, column 32", "unexpected text after the end"});
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[1,1],[0,0]]]}\n}"),
                   {"GeoJSON line 2, column 1", "expected end of input"});
}

TEST(cliBadInput, TruncatedText) {
  expect_invalid_a("POLYGON((0 0,2 0,2 2,0 2,0 0)", {"line 1, column 30", "unexpected end of input"});
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1])"),
                   {"GeoJSON line 1", "unexpected end of input"});
  expect_invalid_a(dir.write("a.json", R"({"rings":[[[0,0],[1,0)"), {"native JSON line 1", "unexpected end of input"});
}

TEST(cliBadInput, UnknownGeometryType) {
  expect_invalid_a("TRIANGLE((0 0,2 0,2 2,0 0))", {"line 1, column 1", "TRIANGLE is not supported"});
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"Circle","coordinates":[0,0]})"),
                   {"GeoJSON at type", "unknown GeoJSON type \"Circle\""});
}

TEST(cliBadInput, LineStringInput) {
  expect_invalid_a("LINESTRING(0 0,2 0)", {"LINESTRING is not a polygonal geometry"});
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"LineString","coordinates":[[0,0],[1,0]]})"),
                   {"GeoJSON at top level", "LineString is not a polygonal geometry"});
}

TEST(cliBadInput, NestedGeometryCollections) {
  expect_invalid_a("GEOMETRYCOLLECTION(GEOMETRYCOLLECTION(POLYGON((0 0,2 0,2 2,0 2,0 0))))",
                   {"line 1, column 20", "nested GEOMETRYCOLLECTION is not supported"});
  TempDir dir;
  expect_invalid_a(
      dir.write("a.geojson",
                R"({"type":"GeometryCollection","geometries":[{"type":"GeometryCollection","geometries":[]}]})"),
      {"GeoJSON at geometries[0]", "nested GeometryCollection is not supported"});
}

TEST(cliBadInput, CrossingEdgesInsideOnePolygonNameTheInputAndBothEdges) {
  // A bow-tie: edge 1-2 crosses edge 3-0. Not orientable, so it cannot be repaired. The
  // message names the input, the ring and both edges by their end points, in plain words
  // (issue 10, item 5).
  expect_invalid_a("POLYGON((0 0,1 0,0 1,1 1,0 0))",
                   {"A (inline WKT): polygon 0, ring 0: its edge from (1 1) to (0 0) crosses its edge from (1 0) to "
                    "(0 1); the edges of a polygon may touch but must not cross"});
  expect_invalid({"union", square_b, "POLYGON((0 0,1 0,0 1,1 1,0 0))"}, {"B (inline WKT): polygon 0, ring 0", "crosses"});
  // Edges of two rings, in GeoJSON (rings named by their paths) and in native JSON, which
  // the library checks (rings named by index).
  TempDir dir;
  expect_invalid_a(dir.write("a.geojson", R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],)"
                                          R"([[-1,1],[2,1],[2,2],[-1,2],[-1,1]]]})"),
                   {"A (file '", "a.geojson'): the edge from (-1 1) to (2 1) of coordinates[1] crosses the edge from "
                                 "(0 4) to (0 0) of coordinates[0]"});
  expect_invalid_a(dir.write("a.json", R"({"rings":[[[0,0],[4,0],[4,4],[0,4]],[[-1,1],[2,1],[2,2],[-1,2]]]})"),
                   {"A (file '", "a.json'): the edge from ", " of rings[1] crosses the edge from ", " of rings[0]"});
}

TEST(cliBadInput, MultiPartInputIsNeverReinterpreted) {
  // issue 10, item 4: each reproducer was read by nesting and gave another answer.
  TempDir dir;
  const std::string fc = dir.write(
      "fc.geojson",
      R"({"type":"FeatureCollection","features":[)"
      R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]]]}},)"
      R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[4,4],[6,4],[6,6],[4,6],[4,4]]]}}]})");
  expect_invalid({"union", fc, "POLYGON EMPTY", "--stats"},
                 {"A (file '", "features[1].geometry.coordinates lies inside features[0].geometry.coordinates",
                  "must not overlap"});
  const std::string twice = "MULTIPOLYGON(((0 0,10 0,10 10,0 10,0 0)),((0 0,10 0,10 10,0 10,0 0)))";
  expect_invalid({"intersection", twice, twice}, {"A (inline WKT): polygon 1 repeats polygon 0"});
  expect_invalid_a("POLYGON((0 0,10 0,10 10,0 10,0 0),(20 20,22 20,22 22,20 22,20 20))",
                   {"polygon 0, ring 1 (a hole) lies outside its shell (polygon 0, ring 0)"});
  expect_invalid_a("POLYGON((0 0,10 0,10 10,0 10,0 0),(1 1,8 1,8 8,1 8,1 1),(2 2,4 2,4 4,2 4,2 2))",
                   {"polygon 0, ring 2 (a hole) lies inside polygon 0, ring 1 (a hole)"});
  expect_invalid_a("MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0)),((4 0,6 2,4 4,3 2,4 0)))",
                   {"polygon 0 and polygon 1 overlap (beside the edge from (4 0) to (4 4) of polygon 0, ring 0)"});
  // Parts that touch along an edge or at a point are a coverage: their union, as read.
  const ProcessResult coverage =
      run_mkbool({"union", "MULTIPOLYGON(((0 0,10 0,10 10,0 10,0 0)),((10 0,20 0,20 10,10 10,10 0)))", "POLYGON EMPTY"});
  EXPECT_EQ(coverage.exit_code, 0) << describe(coverage);
  EXPECT_EQ(canonical_wkt(coverage.out), canonical_wkt("POLYGON ((0 0, 10 0, 20 0, 20 10, 10 10, 0 10, 0 0))"));
}

TEST(cliBadInput, HostileBytesAndNumbers) {
  // Bytes that are no text at all, on standard input: refused by the reader, or at the
  // first NUL byte (which no WKT, GeoJSON or JSON text holds) before any parsing.
  std::string garbage(4096, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 2654435761u) >> 13 | 1);
  expect_invalid({"union", "-", square_b}, {"A (standard input): WKT line 1, column 1"}, garbage);
  garbage[1000] = '\0';
  expect_invalid({"union", "-", square_b}, {"A: standard input holds a NUL byte at offset 1000: binary data"}, garbage);
  // A million digits: read, and refused as not representable.
  TempDir dir;
  expect_invalid_a(dir.write("big.wkt", "POLYGON((0 0,1" + std::string(1'000'000, '0') + " 0,0 1,0 0))"),
                   {"x coordinate '1" + std::string(31, '0') + "...' is not representable as a double"});
  expect_invalid_a("POLYGON((0 0,0x1p3 0,0 1,0 0))", {"malformed number '0x1p3'"});
  expect_invalid_a(dir.path().string(), {"is a directory"});
}

// Inputs that never end. Read to their end, they took all memory (exit 1 "out of memory"
// at best, after gigabytes); no polygon text holds a NUL byte, so the first read refuses them.
TEST(cliBadInput, EndlessBinaryInputIsRefusedAtTheFirstRead) {
  expect_invalid_a("/dev/zero", {"A: '/dev/zero' holds a NUL byte at offset 0: binary data"});
  expect_invalid({"union", square_b, "/dev/urandom"}, {"B: '/dev/urandom' holds a NUL byte at offset "});
  const ProcessResult r = run_process({"/bin/sh", "-c", "exec '" + mkbool_exe() + "' union - '" + square_b + "' < /dev/zero"});
  ASSERT_FALSE(r.timed_out) << describe(r);
  EXPECT_EQ(r.exit_code, 3) << describe(r);
  EXPECT_EQ(r.err, "mkbool: error: A: standard input holds a NUL byte at offset 0: binary data, not WKT, GeoJSON or JSON text\n");
}

TEST(cliBadInput, DuplicateConsecutiveVerticesAreAccepted) {
  const ProcessResult r = run_mkbool({"intersection", "POLYGON((0 0,2 0,2 0,2 0,2 2,0 2,0 2,0 0))", square_b});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))")) << describe(r);
  EXPECT_EQ(r.err, "");
}

TEST(cliBadInput, FileThatDoesNotExist) {
  TempDir dir;
  const std::string missing = dir.file("missing.wkt");
  expect_invalid_a(missing, {"A: cannot open '" + missing + "'", "No such file or directory"});
  expect_invalid({"intersection", square_b, missing}, {"B: cannot open"});
}

TEST(cliBadInput, Directory) {
  TempDir dir;
  expect_invalid_a(dir.path().string(), {"A: '" + dir.path().string() + "' is a directory, not a file"});
}

TEST(cliBadInput, EmptyFile) {
  TempDir dir;
  const std::string empty = dir.write("empty.wkt", "");
  expect_invalid_a(empty, {"A: '" + empty + "' is empty", "POLYGON EMPTY"});
  expect_invalid_a(dir.write("blank.wkt", "  \n\t\n"), {"is empty"});
}

TEST(cliBadInput, EmptyStandardInput) {
  expect_invalid({"intersection", "-", square_b}, {"A: standard input is empty"});
}

TEST(cliBadInput, BadStandardInputIsNamed) {
  expect_invalid({"intersection", square_b, "-"}, {"B (standard input): WKT line 3, column 1", "expected '(' or EMPTY after POLYGON"}, "\nPOLYGON\n");
}

TEST(cliBadInput, EmptyPolygonIsValid) {
  // Empty input is a valid case (BRIEF §8), written POLYGON EMPTY.
  const ProcessResult r = run_mkbool({"union", "POLYGON EMPTY", square_b});
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(canonical_wkt(r.out), canonical_wkt("POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))")) << describe(r);
}

}  // namespace
}  // namespace mk::test
