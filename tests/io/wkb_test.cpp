// Tests of the WKB reader and writer: byte orders, type codes, collections, exact doubles,
// the writer's forms, and every malformed byte string rejected with its offset.
// [OGC06-103 §8.2] [OGC06-103 §6.1.11]
// Preconditions: none. Byte strings are built here field by field, independently of the
// writer, so that reader and writer are each checked against the encoding itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/wkb.hpp"
#include "io/wkt.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

using test::rejects;

// A WKB byte string built field by field in the chosen byte order.
class Bytes {
 public:
  explicit Bytes(bool little = true) : little_(little) {}
  Bytes& order(bool little) {
    little_ = little;
    s_.push_back(little ? '\x01' : '\x00');
    return *this;
  }
  Bytes& u32(std::uint32_t v) { return raw(&v, 4); }
  Bytes& f64(double v) { return raw(&v, 8); }
  Bytes& header(std::uint32_t type) { return order(little_).u32(type); }
  Bytes& ring(const std::vector<Point>& closed) {
    u32(static_cast<std::uint32_t>(closed.size()));
    for (const Point& p : closed) f64(p.x).f64(p.y);
    return *this;
  }
  std::string str() const { return s_; }

 private:
  Bytes& raw(const void* p, std::size_t n) {
    char b[8];
    std::memcpy(b, p, n);
    if (!little_) {  // tests run on little-endian hosts (x86-64, checked below)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    }
    s_.append(b, n);
    return *this;
  }
  bool little_;
  std::string s_;
};

static_assert(std::endian::native == std::endian::little, "the byte strings above assume a little-endian host");

const std::vector<Point> triangle{{0, 0}, {4, 0}, {0, 4}, {0, 0}};
const std::vector<Point> hole{{1, 1}, {1, 2}, {2, 1}, {1, 1}};

TEST(ioWkb, ReadsPolygonInBothByteOrders) {
  for (const bool little : {true, false}) {
    const std::string wkb = Bytes(little).header(3).u32(2).ring(triangle).ring(hole).str();
    const MultiPolygon mp = read_wkb(wkb);
    ASSERT_EQ(mp.size(), 1u) << "little endian " << little;
    EXPECT_EQ(mp[0].shell, (Ring{{0, 0}, {4, 0}, {0, 4}}));
    ASSERT_EQ(mp[0].holes.size(), 1u);
    EXPECT_EQ(mp[0].holes[0], (Ring{{1, 1}, {1, 2}, {2, 1}}));
  }
}

TEST(ioWkb, ReadsMultiPolygonWhosePartsHaveTheirOwnByteOrder) {
  Bytes b(false);
  b.header(6).u32(2);
  b.order(true).u32(3).u32(1).ring(triangle);
  b.order(false).u32(3).u32(1).ring({{10, 10}, {11, 10}, {10, 11}, {10, 10}});
  const MultiPolygon mp = read_wkb(b.str());
  ASSERT_EQ(mp.size(), 2u);
  EXPECT_EQ(mp[1].shell, (Ring{{10, 10}, {11, 10}, {10, 11}}));
}

TEST(ioWkb, ReadsFlatCollectionsEmptiesAndSrid) {
  Bytes b;
  b.header(7).u32(3);
  b.header(3).u32(0);                       // POLYGON EMPTY
  b.header(6).u32(1).header(3).u32(1).ring(triangle);
  b.header(3).u32(2).ring(triangle).u32(0);  // an empty hole adds nothing
  const MultiPolygon mp = read_wkb(b.str());
  ASSERT_EQ(mp.size(), 2u);
  EXPECT_TRUE(mp[1].holes.empty());
  EXPECT_TRUE(read_wkb(Bytes().header(3).u32(0).str()).empty());
  // PostGIS extended WKB with an SRID (shapely writes it when the geometry has one).
  const MultiPolygon srid = read_wkb(Bytes().header(3 | 0x20000000u).u32(4326).u32(1).ring(triangle).str());
  ASSERT_EQ(srid.size(), 1u);
}

TEST(ioWkb, KeepsEveryBitOfEveryDouble) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double big = std::numeric_limits<double>::max();
  const std::vector<Point> ring{{0.1, -2.5e-310}, {big, tiny}, {1.0 / 3.0, big}, {0.1, -2.5e-310}};
  const MultiPolygon mp = read_wkb(Bytes().header(3).u32(1).ring(ring).str());
  ASSERT_EQ(mp[0].shell.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(std::memcmp(&mp[0].shell[i], &ring[i], sizeof(Point)), 0) << i;
  }
  // And the writer gives them back bit for bit, whatever their order on the ring.
  const MultiPolygon again = read_wkb(write_wkb(mp));
  ASSERT_EQ(again.size(), 1u);
  std::vector<Point> a = again[0].shell, b = mp[0].shell;
  std::sort(a.begin(), a.end(), [](Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  std::sort(b.begin(), b.end(), [](Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  EXPECT_EQ(a, b);
}

TEST(ioWkb, WriterFormsMatchTheEncoding) {
  // Shell clockwise, hole counterclockwise: the writer turns both around, as in WKT.
  const MultiPolygon mp{OgcPolygon{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}}};
  const std::string expected = Bytes()
                                   .header(3)
                                   .u32(2)
                                   .ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}})
                                   .ring({{1, 1}, {1, 2}, {2, 2}, {2, 1}, {1, 1}})
                                   .str();
  EXPECT_EQ(write_wkb(mp), expected);
  EXPECT_EQ(write_wkb(MultiPolygon{}), Bytes().header(3).u32(0).str());
  const MultiPolygon two{OgcPolygon{{{0, 0}, {1, 0}, {0, 1}}, {}}, OgcPolygon{{{5, 5}, {6, 5}, {5, 6}}, {}}};
  Bytes m;
  m.header(6).u32(2);
  m.header(3).u32(1).ring({{0, 0}, {1, 0}, {0, 1}, {0, 0}});
  m.header(3).u32(1).ring({{5, 5}, {6, 5}, {5, 6}, {5, 5}});
  EXPECT_EQ(write_wkb(two), m.str());
}

TEST(ioWkb, WriterPutsNonRegularPartsInACollection) {
  Output o;
  o.dangling_edges.push_back({{2, 0}, {2, 2}});
  o.isolated_points.push_back({3, 3});
  Bytes b;
  b.header(7).u32(2);
  b.header(2).u32(2).f64(2).f64(0).f64(2).f64(2);
  b.header(1).f64(3).f64(3);
  EXPECT_EQ(write_wkb(o), b.str());
  Output unbounded;
  unbounded.unbounded = true;
  EXPECT_TRUE(rejects([&] { write_wkb(unbounded); }, "unbounded"));
}

TEST(ioWkb, AgreesWithTheWktReader) {
  const char* wkt = "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 3, 3 3, 3 2, 2 2)), ((20 0, 21 0, 20 1, 20 0)))";
  const MultiPolygon mp = read_wkt(wkt);
  EXPECT_EQ(write_wkt(read_wkb(write_wkb(mp))), write_wkt(mp));
}

TEST(ioWkb, RejectsMalformedInputWithTheOffset) {
  EXPECT_TRUE(rejects([] { read_wkb(""); }, "WKB byte 0: empty input"));
  EXPECT_TRUE(rejects([] { read_wkb("\x02"); }, "WKB byte 0: byte order 2 is neither"));
  EXPECT_TRUE(rejects([] { read_wkb(std::string("\x01\x03\x00", 3)); }, "WKB byte 1: unexpected end of input; expected a geometry type"));
  // A count larger than the bytes that follow could hold: refused before any allocation.
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(0xFFFFFFFFu).str()); },
                      "WKB byte 5 (polygon 0): ring count 4294967295 needs at least"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).u32(1000000).f64(0).str()); },
                      "WKB byte 9 (polygon 0, ring 0): point count 1000000"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).u32(2).f64(0).f64(0).f64(1).str()); },
                      "(polygon 0, ring 0): point count 2 needs at least 32 more bytes, only 24 left"));
  // Z and M: one count of coordinates per vertex for the whole input, the extra ones finite.
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(7).u32(2).header(3).u32(0).header(1003).u32(0).str()); },
                      "WKB byte 19: Polygon has 3 coordinates per vertex, but the geometries before have 2"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(1003 | 0x80000000u).u32(0).str()); },
                      "WKB byte 1: geometry type 1003 has both ISO and extended Z/M flags"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(1003).u32(1).u32(1).f64(0).f64(0).f64(std::nan("")).str()); },
                      "WKB byte 29 (polygon 0, ring 0, vertex 0): third coordinate is not finite"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3003).u32(1).u32(3).f64(0).str()); },
                      "point count 3 needs at least 96 more bytes, only 8 left"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(2).u32(0).str()); },
                      "LineString is not a polygonal geometry"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(17).u32(0).str()); }, "Triangle is not supported"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(99).u32(0).str()); }, "unknown geometry type 99"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(7).u32(1).header(7).u32(0).str()); },
                      "WKB byte 9: nested GeometryCollection is not supported"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(6).u32(1).header(2).u32(0).str()); },
                      "a MultiPolygon holds Polygons only"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(0).str() + "x"); },
                      "WKB byte 9: 1 bytes after the end of the geometry"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).ring({{0, 0}, {1, std::nan("")}, {0, 1}, {0, 0}}).str()); },
                      "WKB byte 29 (polygon 0, ring 0, vertex 1): y coordinate is not finite"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).ring({{0, 0}, {1, 0}, {0, 1}, {0, 2}}).str()); },
                      "(polygon 0, ring 0, vertex 3): ring is not closed"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).ring({{0, 0}, {1, 0}, {0, 0}}).str()); },
                      "(polygon 0, ring 0): ring has 3 coordinates"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).ring({{0, 0}, {1, 0}, {1, 0}, {0, 0}}).str()); },
                      "fewer than 3 distinct points"));
  EXPECT_TRUE(rejects([] { read_wkb(Bytes().header(3).u32(1).u32(0).str()); },
                      "(polygon 0, ring 0): a shell ring cannot be empty"));
}

// Z and M coordinates (ISO codes and PostGIS's flags, as shapely writes a 3D polygon) are
// read and dropped: the same rings as the 2D encoding.
TEST(ioWkb, DropsZAndM) {
  const std::vector<Point> ring = {{0, 0}, {4, 0}, {0, 4}, {0, 0}};
  const std::string flat = write_wkt(read_wkb(Bytes().header(3).u32(1).ring(ring).str()));
  for (const std::uint32_t type : {1003u, 2003u, 3 | 0x80000000u, 3 | 0x40000000u, 3003u, 3 | 0xC0000000u}) {
    const int extra = (type == 3003u || type == (3 | 0xC0000000u)) ? 2 : 1;
    Bytes b;
    b.header(type).u32(1).u32(static_cast<std::uint32_t>(ring.size()));
    for (const Point& p : ring) {
      b.f64(p.x).f64(p.y);
      for (int c = 0; c < extra; ++c) b.f64(7.5);
    }
    EXPECT_EQ(write_wkt(read_wkb(b.str())), flat) << "type " << type;
  }
  Bytes multi;
  multi.header(6 | 0x80000000u).u32(1).header(3 | 0x80000000u).u32(1).u32(4);
  for (const Point& p : ring) multi.f64(p.x).f64(p.y).f64(1);
  EXPECT_EQ(write_wkt(read_wkb(multi.str())), flat);
}

// Every prefix of a valid byte string is an error, never a crash or a partial result.
TEST(ioWkb, EveryTruncationIsRejected) {
  Bytes b;
  b.header(7).u32(2).header(3).u32(2).ring(triangle).ring(hole).header(6).u32(1).header(3).u32(1).ring(triangle);
  const std::string full = b.str();
  ASSERT_EQ(read_wkb(full).size(), 2u);
  for (std::size_t n = 0; n < full.size(); ++n) {
    EXPECT_THROW(read_wkb(full.substr(0, n)), InvalidInput) << "prefix of " << n << " bytes";
  }
}

}  // namespace
}  // namespace mk
