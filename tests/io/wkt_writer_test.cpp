// Tests of the WKT writer: forms, ring direction, closing, shortest round-trip numbers,
// non-regular parts, and the unbounded error. [OGC06-103 §7] [OGC06-103 §6.1.11]
// Preconditions: none.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "io/wkt.hpp"
#include "test_util.hpp"

namespace mk {
namespace {

using test::rejects;

OgcPolygon square_with_hole() {
  // Shell clockwise and hole counterclockwise: the writer must turn both around.
  return OgcPolygon{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}};
}

TEST(ioWktWriter, EmptyIsPolygonEmpty) {
  EXPECT_EQ(write_wkt(MultiPolygon{}), "POLYGON EMPTY");
  EXPECT_EQ(write_wkt(Output{}), "POLYGON EMPTY");
}

TEST(ioWktWriter, ShellsCounterclockwiseHolesClockwiseRingsClosed) {
  EXPECT_EQ(write_wkt(MultiPolygon{square_with_hole()}),
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))");
}

TEST(ioWktWriter, SeveralPolygonsAreMultiPolygon) {
  const MultiPolygon mp{OgcPolygon{{{0, 0}, {1, 0}, {0, 1}}, {}},
                        OgcPolygon{{{5, 5}, {6, 5}, {5, 6}}, {}}};
  EXPECT_EQ(write_wkt(mp), "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6, 5 5)))");
}

TEST(ioWktWriter, ZeroAreaRingIsWrittenAsGiven) {
  const MultiPolygon mp{OgcPolygon{{{0, 0}, {2, 0}, {1, 0}}, {}}};
  EXPECT_EQ(write_wkt(mp), "POLYGON ((0 0, 2 0, 1 0, 0 0))");
}

TEST(ioWktWriter, OrientationIsExactForNeedleThinRings) {
  // The middle vertex is one ulp above the chord: a counterclockwise sliver whose
  // double-precision area is easy to get wrong; it must be written unchanged.
  const double up = std::nextafter(0.5, 1.0);
  const MultiPolygon ccw{OgcPolygon{{{0, 0}, {1, 1}, {0.5, up}}, {}}};
  EXPECT_EQ(read_wkt(write_wkt(ccw))[0].shell, ccw[0].shell);
  const MultiPolygon cw{OgcPolygon{{{0, 0}, {0.5, up}, {1, 1}}, {}}};
  EXPECT_EQ(read_wkt(write_wkt(cw))[0].shell, ccw[0].shell);
}

TEST(ioWktWriter, RoundTripKeepsEveryBit) {
  const double values[] = {0.1,
                           1.0 / 3.0,
                           -2.5e-310,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           -std::numeric_limits<double>::max(),
                           123456789.123456789,
                           std::nextafter(1.0, 2.0)};
  Ring shell;
  double x = 0;
  for (double v : values) shell.push_back({x++, v});
  const MultiPolygon mp{OgcPolygon{shell, {}}};
  const std::string text = write_wkt(mp);
  const MultiPolygon back = read_wkt(text);
  ASSERT_EQ(back.size(), 1u) << text;
  // The ring may have been reversed; compare as sets of points in either direction.
  const Ring& r = back[0].shell;
  ASSERT_EQ(r.size(), shell.size());
  const bool same = r == shell;
  Ring reversed{shell.front()};
  for (std::size_t i = shell.size() - 1; i > 0; --i) reversed.push_back(shell[i]);
  EXPECT_TRUE(same || r == reversed) << text;
  EXPECT_NE(text.find("0.1,"), std::string::npos) << "0.1 is not written in shortest form: " << text;
}

TEST(ioWktWriter, WriteThenReadIsIdentityForNormalisedPolygons) {
  const MultiPolygon mp{OgcPolygon{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}},
                        OgcPolygon{{{10, 0}, {12, 0}, {11, 0.5}}, {}}};
  const MultiPolygon back = read_wkt(write_wkt(mp));
  ASSERT_EQ(back.size(), mp.size());
  for (std::size_t i = 0; i < mp.size(); ++i) {
    EXPECT_EQ(back[i].shell, mp[i].shell);
    EXPECT_EQ(back[i].holes, mp[i].holes);
  }
}

TEST(ioWktWriter, DanglingEdgesAndIsolatedPointsMakeACollection) {
  Output out;
  out.polygons = {OgcPolygon{{{0, 0}, {1, 0}, {0, 1}}, {}}};
  out.dangling_edges = {{{1, 0}, {2, 0}}};
  out.isolated_points = {{5, 5}};
  EXPECT_EQ(write_wkt(out),
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)), LINESTRING (1 0, 2 0), "
            "POINT (5 5))");
  out.polygons.push_back(OgcPolygon{{{7, 7}, {8, 7}, {7, 8}}, {}});
  EXPECT_EQ(write_wkt(out).rfind("GEOMETRYCOLLECTION (MULTIPOLYGON (((0 0", 0), 0u);
}

TEST(ioWktWriter, OnlyNonRegularParts) {
  Output out;
  out.dangling_edges = {{{0, 0}, {1, 1}}};
  EXPECT_EQ(write_wkt(out), "GEOMETRYCOLLECTION (LINESTRING (0 0, 1 1))");
  out.dangling_edges.clear();
  out.isolated_points = {{-0.5, 2}};
  EXPECT_EQ(write_wkt(out), "GEOMETRYCOLLECTION (POINT (-0.5 2))");
}

TEST(ioWktWriter, UnboundedResultIsAnError) {
  Output out;
  out.unbounded = true;
  EXPECT_TRUE(rejects([&] { write_wkt(out); },
                      "the result is unbounded (hole type) and cannot be written as WKT; use "
                      "--format json"));
}

// A large output is formatted in parts on several threads: the text is the same, byte for
// byte, as on one thread, and as written point by point here (a clockwise shell of 100,000
// points that must be turned around, a hole, a second polygon, non-regular parts).
TEST(ioWktWriter, ThreadsWriteTheSameBytes) {
  const std::size_t n = 100'000;
  Ring shell;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = -2 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
    shell.push_back({100 * std::cos(t), 100 * std::sin(t) + 1e-7 * static_cast<double>(i % 7)});
  }
  Output out;
  out.polygons = {OgcPolygon{shell, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}}, OgcPolygon{{{300, 0}, {301, 0}, {300, 1}}, {}}};
  std::string expected = "GEOMETRYCOLLECTION (MULTIPOLYGON (((";
  const auto point = [](const Point& p) {
    const auto text = [](double v) {
      char buf[32];
      if (v == 0) v = 0;  // "-0" is written "0"
      return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
    };
    return text(p.x) + " " + text(p.y);
  };
  for (std::size_t i = 0; i <= n; ++i) expected += (i ? ", " : "") + point(shell[(n - i % n) % n]);
  expected += "), (1 1, 1 2, 2 2, 2 1, 1 1)), ((300 0, 301 0, 300 1, 300 0))), LINESTRING (1 0, 2 0), POINT (5 5))";
  out.dangling_edges = {{{1, 0}, {2, 0}}};
  out.isolated_points = {{5, 5}};
  EXPECT_EQ(write_wkt(out, 1), expected);
  for (const unsigned threads : {0u, 2u, 3u}) EXPECT_EQ(write_wkt(out, threads), expected) << threads << " threads";
  EXPECT_EQ(write_wkt(out.polygons, 2), write_wkt(out.polygons, 1));
}

// Many groups of pieces (more than one wave of them on every thread count here): 40,000
// small polygons with holes between two rings of 150,000 points, each group formatted apart
// and joined in order; the text is the one written point by point here.
TEST(ioWktWriter, ThreadsWriteTheSameBytesOverManyWaves) {
  const auto text = [](double v) {
    char buf[32];
    if (v == 0) v = 0;
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  };
  const auto ring_text = [&](const Ring& r) {  // closed, as given (already in the written direction)
    std::string s = "(";
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const Point& p = r[i % r.size()];
      s += (i ? ", " : "") + text(p.x) + " " + text(p.y);
    }
    return s + ")";
  };
  const auto big_ring = [](double cx) {  // counterclockwise
    Ring r;
    const std::size_t n = 150'000;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
      r.push_back({cx + 1000 * std::cos(t), 1000 * std::sin(t) + 1e-9 * static_cast<double>(i % 5)});
    }
    return r;
  };
  MultiPolygon polygons;
  polygons.push_back({big_ring(0), {}});
  for (int i = 0; i < 40'000; ++i) {
    const double x = 5000 + 0.1 * i, y = 0.3 + 1e-3 * (i % 11);
    polygons.push_back({{{x, 0}, {x + 0.05, 0}, {x + 0.05, 1}, {x, 1}}, {}});
    if (i % 3 == 0) polygons.back().holes.push_back({{x + 0.01, y}, {x + 0.01, y + 0.1}, {x + 0.02, y + 0.1}, {x + 0.02, y}});
  }
  polygons.push_back({big_ring(9000), {}});
  std::string expected = "MULTIPOLYGON (";
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    expected += (k ? ", (" : "(") + ring_text(polygons[k].shell);
    for (const Ring& h : polygons[k].holes) expected += ", " + ring_text(h);
    expected += ")";
  }
  expected += ")";
  for (const unsigned threads : {1u, 2u, 3u, 5u}) EXPECT_EQ(write_wkt(polygons, threads), expected) << threads << " threads";
}

}  // namespace
}  // namespace mk
