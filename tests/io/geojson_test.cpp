// Tests of the GeoJSON reader and writer: geometry, feature and collection forms, ring
// validation with element paths, syntax errors with line and column, right-hand rule.
// [RFC7946 §3] [RFC7946 §3.1.6]
// Preconditions: none.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "io/geojson.hpp"
#include "io/wkt.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

using test::rejects;

constexpr const char* square_coordinates = "[[[0,0],[4,0],[4,4],[0,4],[0,0]]]";

std::string polygon_json(const std::string& coordinates) {
  return R"({"type":"Polygon","coordinates":)" + coordinates + "}";
}

Ring square() { return {{0, 0}, {4, 0}, {4, 4}, {0, 4}}; }

TEST(ioGeoJson, ReadsPolygon) {
  const MultiPolygon mp = read_geojson(polygon_json(square_coordinates));
  ASSERT_EQ(mp.size(), 1u);
  EXPECT_EQ(mp[0].shell, square());
}

TEST(ioGeoJson, ReadsPolygonWithHoleAndFloatCoordinates) {
  const MultiPolygon mp = read_geojson(
      polygon_json("[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1.5,1],[1,2e0],[2,2],[1.5,1]]]"));
  ASSERT_EQ(mp[0].holes.size(), 1u);
  EXPECT_EQ(mp[0].holes[0], (Ring{{1.5, 1}, {1, 2}, {2, 2}}));
}

TEST(ioGeoJson, ReadsMultiPolygonAndCollection) {
  EXPECT_EQ(read_geojson(R"({"type":"MultiPolygon","coordinates":[)" + std::string(square_coordinates) +
                         "," + square_coordinates + "]}")
                .size(),
            2u);
  EXPECT_EQ(read_geojson(R"({"type":"GeometryCollection","geometries":[)" +
                         polygon_json(square_coordinates) + "," + polygon_json("[]") + "]}")
                .size(),
            1u);
}

TEST(ioGeoJson, MergesFeaturesOfACollection) {
  const std::string text = R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"name":"a"},"geometry":)" +
                           polygon_json(square_coordinates) + R"(},
    {"type":"Feature","properties":null,"geometry":null},
    {"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[[[[10,10],[11,10],[10,11],[10,10]]]]}}
  ]})";
  const MultiPolygon mp = read_geojson(text);
  ASSERT_EQ(mp.size(), 2u);
  EXPECT_EQ(mp[1].shell, (Ring{{10, 10}, {11, 10}, {10, 11}}));
  EXPECT_EQ(read_geojson(R"({"type":"Feature","geometry":)" + polygon_json(square_coordinates) + "}")
                .size(),
            1u);
}

TEST(ioGeoJson, EmptyFormsGiveNoPolygons) {
  EXPECT_TRUE(read_geojson(polygon_json("[]")).empty());
  EXPECT_TRUE(read_geojson(R"({"type":"FeatureCollection","features":[]})").empty());
  EXPECT_TRUE(read_geojson(R"({"type":"GeometryCollection","geometries":[]})").empty());
}

TEST(ioGeoJson, RemovesRepeatedConsecutiveVertices) {
  EXPECT_EQ(read_geojson(polygon_json("[[[0,0],[0,0],[4,0],[4,4],[4,4],[0,4],[0,0],[0,0]]]"))[0].shell,
            square());
}

TEST(ioGeoJson, SyntaxErrorsHaveLineAndColumn) {
  EXPECT_TRUE(rejects(
      [] { read_geojson("{\n  \"type\": \"Polygon\",\n  \"coordinates\": [[[0, 0],, [1, 0]]]\n}"); },
      "GeoJSON line 3, column 27: syntax error while parsing value - unexpected ','"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"Polygon")"); },
                      "GeoJSON line 1, column 18: syntax error while parsing object - unexpected end of "
                      "input"));
  EXPECT_TRUE(rejects([] { read_geojson("  "); }, "GeoJSON line 1, column 1: empty input"));
}

TEST(ioGeoJson, ErrorsNameThePathOfTheElement) {
  const std::string text = R"({"type":"FeatureCollection","features":[
    {"type":"Feature","geometry":null},
    {"type":"Feature","geometry":)" + polygon_json(square_coordinates) + R"(},
    {"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4]]]}}]})";
  EXPECT_TRUE(rejects([&] { read_geojson(text); },
                      "GeoJSON at features[2].geometry.coordinates[0][3]: ring is not closed: "
                      "last vertex (0 4) differs from first vertex (0 0)"));
}

TEST(ioGeoJson, RejectsRingsWithTooFewPoints) {
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[1,0],[0,0]]]")); },
                      "GeoJSON at coordinates[0]: ring has 3 coordinates; a closed ring needs at "
                      "least 4"));
  EXPECT_TRUE(rejects(
      [] {
        read_geojson(R"({"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1],[0,0]]],)"
                     R"([[[0,0],[4,0],[4,4],[0,0]],[[1,1],[2,1],[1,1],[2,1],[1,1]]]]})");
      },
      "GeoJSON at coordinates[1][1]: ring has fewer than 3 distinct points"));
}

TEST(ioGeoJson, ReadsAltitudeAndDropsIt) {
  // issue 10, item 5: RFC 7946 §3.1.1 allows an altitude (and, discouraged, more elements).
  const MultiPolygon mp = read_geojson(polygon_json("[[[0,0,5],[1,0,6.5],[0,1],[0,0,1,2]]]"));
  ASSERT_EQ(mp.size(), 1u);
  EXPECT_EQ(mp[0].shell, (Ring{{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json(R"([[[0,0],[1,0,"high"],[0,1],[0,0]]])")); },
                      "GeoJSON at coordinates[0][1][2]: expected a number, found a string"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[1,0,1e999],[0,1],[0,0]]]")); }, "1e999"));
}

TEST(ioGeoJson, RejectsBadPositions) {
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[1],[0,1],[0,0]]]")); },
                      "GeoJSON at coordinates[0][1]: position has 1 coordinates; expected [x, y] or [x, y, altitude]"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json(R"([[[0,0],[1,"0"],[0,1],[0,0]]])")); },
                      "GeoJSON at coordinates[0][1][1]: expected a number, found a string"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[1,null],[0,1],[0,0]]]")); },
                      "GeoJSON at coordinates[0][1][1]: expected a number, found null"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[0]")); },
                      "GeoJSON at coordinates[0]: expected an array of positions, found a number"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[9007199254740993,0],[0,1],[0,0]]]")); },
                      "GeoJSON at coordinates[0][1][0]: integer coordinate 9007199254740993 is not "
                      "exactly a double"));
}

TEST(ioGeoJson, RejectsNonFiniteNumbers) {
  // JSON has no NaN or infinity literals; an overflowing number is the only way in.
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[1e400,0],[0,1],[0,0]]]")); },
                      "GeoJSON: number overflow parsing '1e400'"));
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,0],[NaN,0],[0,1],[0,0]]]")); },
                      "GeoJSON line 1, column 42: syntax error"));
}

TEST(ioGeoJson, RejectsNonzeroNumbersThatWouldReadAsZero) {
  // 1e-400 read as 0 moved the vertex without a word (WKT refused it already).
  EXPECT_TRUE(rejects([] { read_geojson(polygon_json("[[[0,-1],[-1e-400,0],[0,1],[-1,0],[0,-1]]]")); },
                      "GeoJSON at coordinates[0][1][0]: coordinate is not representable as a double (not zero, "
                      "but too small in magnitude: it would be read as 0)"));
  const std::string long_fraction = "0." + std::string(330, '0') + "1";
  EXPECT_TRUE(rejects([&] { read_geojson(polygon_json("[[[0,0],[2,0],[" + long_fraction + ",1],[0,0]]]")); },
                      "GeoJSON at coordinates[0][2][0]: coordinate is not representable as a double"));
  // Zeros in any spelling, such numbers where they are no coordinates (properties, bbox),
  // and the smallest subnormals are read.
  const MultiPolygon read = read_geojson(
      R"({"type":"Feature","bbox":[1e-400,0,2,1],"properties":{"note":"1e-400 \" 1e-999","v":1e-999},)"
      R"("geometry":{"type":"Polygon",)"
      R"("coordinates":[[[0e-999,0.0E+5],[-0.000e-400,1],[2.4703282292062328e-324,1],[0,0]]]}})");
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].shell.size(), 3u);
  EXPECT_EQ(read[0].shell[1].x, 0.0);
  EXPECT_EQ(read[0].shell[2].x, 4.9406564584124654e-324);
}

TEST(ioGeoJson, RejectsWrongTypes) {
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"LineString","coordinates":[[0,0],[1,1]]})"); },
                      "GeoJSON at top level: LineString is not a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"Polygonn","coordinates":[]})"); },
                      "GeoJSON at type: unknown GeoJSON type \"Polygonn\""));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"coordinates":[]})"); },
                      "GeoJSON at top level: missing \"type\" member"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"Polygon"})"); },
                      "GeoJSON at top level: missing \"coordinates\" member"));
  EXPECT_TRUE(rejects([] { read_geojson("[1, 2]"); },
                      "GeoJSON at top level: expected a GeoJSON object, found an array"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"hole","rings":[]})"); },
                      "island and hole polygons are the native JSON format"));
  EXPECT_TRUE(rejects(
      [] {
        read_geojson(R"({"type":"FeatureCollection","features":[{"type":"Feature","geometry":)"
                     R"({"type":"Point","coordinates":[0,0]}}]})");
      },
      "GeoJSON at features[0].geometry: Point is not a polygonal geometry"));
  EXPECT_TRUE(rejects(
      [] {
        read_geojson(R"({"type":"FeatureCollection","features":[)" + polygon_json("[]") + "]}");
      },
      "GeoJSON at features[0].type: expected \"Feature\", found \"Polygon\""));
}

TEST(ioGeoJson, RejectsNestedGeometryCollection) {
  EXPECT_TRUE(rejects(
      [] {
        read_geojson(R"({"type":"GeometryCollection","geometries":[)"
                     R"({"type":"GeometryCollection","geometries":[]}]})");
      },
      "GeoJSON at geometries[0]: nested GeometryCollection is not supported"));
}

TEST(ioGeoJson, DeepNestingFailsWithoutRecursion) {
  const std::string deep = R"({"type":"Polygon","coordinates":)" + std::string(100000, '[') +
                           std::string(100000, ']') + "}";
  EXPECT_TRUE(rejects([&] { read_geojson(deep); },
                      "GeoJSON at coordinates[0][0]: position has 1 coordinates"));
}

TEST(ioGeoJson, WriterFollowsTheRightHandRule) {
  const MultiPolygon mp{OgcPolygon{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}}};
  EXPECT_EQ(write_geojson(mp),
            R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],)"
            R"([[1,1],[1,2],[2,2],[2,1],[1,1]]]})");
}

TEST(ioGeoJson, WriterForms) {
  EXPECT_EQ(write_geojson(MultiPolygon{}), R"({"type":"Polygon","coordinates":[]})");
  const MultiPolygon two{OgcPolygon{{{0, 0}, {1, 0}, {0, 1}}, {}}, OgcPolygon{{{5, 5}, {6, 5}, {5, 6}}, {}}};
  const std::string text = write_geojson(two);
  EXPECT_EQ(text.rfind(R"({"type":"MultiPolygon")", 0), 0u);
  EXPECT_TRUE(nlohmann::json::accept(text));
  EXPECT_EQ(read_geojson(text).size(), 2u);
}

// A member the reader reads, given twice in one object, is refused with its path (nlohmann
// would keep the last value, other readers the first); repeated names the reader does not
// read (in properties, in foreign members) are left alone like their values. [RFC8259 §4]
TEST(ioGeoJson, RepeatedMembersItReadsAreRefusedWithTheirPath) {
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]],"coordinates":[]})"); },
                      "GeoJSON at coordinates: member \"coordinates\" is repeated"));
  EXPECT_TRUE(rejects(
      [] {
        read_geojson(R"({"type":"FeatureCollection","features":[)"
                     R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[]}},)"
                     R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","type":"MultiPolygon","coordinates":[]}}]})");
      },
      "GeoJSON at features[1].geometry.type: member \"type\" is repeated"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"Feature","geometry":null,"geometry":)" + polygon_json(square_coordinates) + "}"); },
                      "GeoJSON at geometry: member \"geometry\" is repeated"));
  EXPECT_TRUE(rejects([] { read_geojson(R"({"type":"GeometryCollection","geometries":[],"geometries":[]})"); },
                      "GeoJSON at geometries: member"));
  // Not read, not refused: repeated names in properties and in a foreign member.
  const MultiPolygon mp = read_geojson(R"({"type":"Feature","properties":{"type":1,"type":2},"crs":{"a":1,"a":2},"geometry":)" +
                                       polygon_json(square_coordinates) + "}");
  ASSERT_EQ(mp.size(), 1u);
  EXPECT_EQ(mp[0].shell, square());
}

TEST(ioGeoJson, WriteThenReadIsIdentity) {
  const MultiPolygon mp{OgcPolygon{{{0.1, 0.2}, {4e-300, 0.3}, {4, 4.5}, {-0.7, 4}},
                                   {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}}};
  const MultiPolygon back = read_geojson(write_geojson(mp));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].shell, mp[0].shell);
  EXPECT_EQ(back[0].holes, mp[0].holes);
  // And across formats: GeoJSON and WKT describe the same polygon.
  EXPECT_EQ(read_wkt(write_wkt(back))[0].shell, mp[0].shell);
}

TEST(ioGeoJson, WriterCollectsNonRegularParts) {
  Output out;
  out.polygons = {OgcPolygon{{{0, 0}, {1, 0}, {0, 1}}, {}}};
  out.dangling_edges = {{{1, 0}, {2, 0}}};
  out.isolated_points = {{5, 5}};
  const std::string text = write_geojson(out);
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["type"], "GeometryCollection");
  ASSERT_EQ(j["geometries"].size(), 3u);
  EXPECT_EQ(j["geometries"][1]["type"], "LineString");
  EXPECT_EQ(j["geometries"][1]["coordinates"], nlohmann::json::parse("[[1,0],[2,0]]"));
  EXPECT_EQ(j["geometries"][2]["coordinates"], nlohmann::json::parse("[5,5]"));
}

TEST(ioGeoJson, UnboundedResultIsAnError) {
  Output out;
  out.unbounded = true;
  EXPECT_TRUE(rejects([&] { write_geojson(out); },
                      "the result is unbounded (hole type) and cannot be written as GeoJSON; use "
                      "--format json"));
}

}  // namespace
}  // namespace mk
