// Tests of format sniffing and of read_polygon's dispatch. [OGC06-103 §7] [RFC7946] [MK89 §2.2]
// Preconditions: none.
#include <gtest/gtest.h>

#include <string>

#include "io/format.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

constexpr const char* wkt = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))";
constexpr const char* geojson = R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]]]})";
constexpr const char* native = R"({"type":"hole","rings":[[[0,0],[4,0],[4,4],[0,4]]]})";

TEST(ioFormat, ByExtension) {
  EXPECT_EQ(sniff_format(geojson, "a.wkt"), Format::wkt);
  EXPECT_EQ(sniff_format(geojson, "dir/A.WKT"), Format::wkt);
  EXPECT_EQ(sniff_format(native, "a.geojson"), Format::geojson);
  EXPECT_EQ(sniff_format(native, "a.json"), Format::native_json);
  EXPECT_EQ(sniff_format(geojson, "a.JSON"), Format::geojson);
}

TEST(ioFormat, ByContent) {
  EXPECT_EQ(sniff_format(wkt, ""), Format::wkt);
  EXPECT_EQ(sniff_format(wkt, "input.txt"), Format::wkt);
  EXPECT_EQ(sniff_format(geojson, "-"), Format::geojson);
  EXPECT_EQ(sniff_format(native, ""), Format::native_json);
  EXPECT_EQ(sniff_format(std::string("\xEF\xBB\xBF \n") + native, ""), Format::native_json);
  EXPECT_EQ(sniff_format("", ""), Format::wkt);
}

TEST(ioFormat, OnlyATopLevelRingsKeyMeansNative) {
  // "rings" as a nested key, as a string value, or inside an escaped string is not native.
  EXPECT_EQ(sniff_format(R"({"type":"Feature","properties":{"rings":1},"geometry":null})", ""),
            Format::geojson);
  EXPECT_EQ(sniff_format(R"({"type":"Feature","properties":{"name":"rings"},"geometry":null})", ""),
            Format::geojson);
  EXPECT_EQ(sniff_format(R"({"note":"a \"rings\": b","rings":[]})", ""), Format::native_json);
  EXPECT_EQ(sniff_format(R"({"a":[{"b":1}],"rings":[]})", ""), Format::native_json);
  EXPECT_EQ(sniff_format(R"({"a":[1,{"rings":1}]})", ""), Format::geojson);
  EXPECT_EQ(sniff_format(R"({"unterminated)", ""), Format::geojson);
}

TEST(ioFormat, ReadPolygonDispatches) {
  const Polygon from_wkt = read_polygon(wkt, "a.wkt");
  EXPECT_EQ(from_wkt.type, PolygonType::island);
  EXPECT_EQ(from_wkt.rings.size(), 2u);  // shell and hole become rings of one island
  EXPECT_EQ(read_polygon(geojson, "").rings.size(), 1u);
  const Polygon from_native = read_polygon(native, "");
  EXPECT_EQ(from_native.type, PolygonType::hole);
}

TEST(ioFormat, ReadPolygonReportsTheFormatsError) {
  EXPECT_TRUE(test::rejects([] { read_polygon("", "a.wkt"); }, "WKT line 1, column 1: empty input"));
  EXPECT_TRUE(test::rejects([] { read_polygon("{", ""); }, "GeoJSON line 1, column 2: syntax error"));
  EXPECT_TRUE(test::rejects([] { read_polygon(R"({"rings": 5})", ""); },
                            "native JSON at rings: expected an array"));
}

TEST(ioFormat, Names) {
  EXPECT_EQ(format_name(Format::wkt), "WKT");
  EXPECT_EQ(format_name(Format::geojson), "GeoJSON");
  EXPECT_EQ(format_name(Format::native_json), "native JSON");
}

}  // namespace
}  // namespace mk
