// Multi-part input is read as its union or refused by name (issue 10, item 4): hand-derived
// cases for every class, and random rectangle sets checked against a cell-by-cell winding
// oracle (independent of the core) and against the area mk::compute gives for what is accepted.
// [OGC06-103 §6.1.11] [MK89 §2.2]
// Preconditions: none.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <random>
#include <tuple>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "io/parts.hpp"
#include "io/wkt.hpp"
#include "tests/io/test_util.hpp"

namespace mk {
namespace {

using test::rejects;

Polygon checked(const std::string& wkt) {
  PartNames names;
  const MultiPolygon mp = read_wkt(wkt, &names.parts);
  return to_checked_polygon(mp, names);
}

::testing::AssertionResult accepted(const std::string& wkt) {
  try {
    const Polygon p = checked(wkt);
    if (p.rings != to_polygon(read_wkt(wkt)).rings) return ::testing::AssertionFailure() << "rings changed";
    return ::testing::AssertionSuccess();
  } catch (const InvalidInput& e) {
    return ::testing::AssertionFailure() << e.what();
  }
}

TEST(ioParts, ValidInputsAndCoveragesAreAccepted) {
  for (const char* wkt : {
           "POLYGON EMPTY",
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))",
           "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0))",                                  // clockwise shell
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1))",       // hole either way
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))",
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (0 0, 2 1, 1 2, 0 0))",            // hole touching at a vertex
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (2 0, 3 1, 1 1, 2 0))",            // ... at a vertex on an edge
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1), (2 2, 3 2, 3 3, 2 3, 2 2))",  // holes touch
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1), (2 1, 3 1, 3 2, 2 2, 2 1))",  // share an edge
           "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (0 0, 5 0, 5 5, 0 5, 0 0))",   // hole along the shell
           "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 4, 8 4, 8 8, 4 8, 4 4)))",           // parts touch
           "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 0, 8 0, 8 4, 4 4, 4 0)))",           // coverage
           "MULTIPOLYGON (((0 0, 4 0, 0 4, 0 0)), ((4 0, 4 4, 0 4, 4 0)))",                    // diagonal coverage
           "MULTIPOLYGON (((0 0, 4 0, 4 2, 0 2, 0 0)), ((1 2, 3 2, 2 4, 1 2)))",               // edge in an edge
           "MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 8 1, 8 8, 1 8, 1 1)), ((3 3, 6 3, 6 6, 3 6, 3 3)))",
           "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0, 1 2, 2 1, 0 0))",         // inverted ring: its loop is a hole
           "POLYGON ((0 0, 1 1, 2 0, 2 2, 1 1, 0 2, 0 0))",              // two loops, same way round
           "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)), POLYGON EMPTY, POLYGON ((5 5, 6 5, 5 6, 5 5)))",
       }) {
    EXPECT_TRUE(accepted(wkt)) << wkt;
  }
}

TEST(ioParts, PartsInsideRepeatingOrOverlappingOthersAreRefusedByName) {
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((2 2, 4 2, 4 4, 2 4, 2 2)))"); },
                      "polygon 1 lies inside polygon 0; the parts of a multi-part polygon must not overlap"));
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((2 2, 4 2, 4 4, 2 4, 2 2)), ((0 0, 10 0, 10 10, 0 10, 0 0)))"); },
                      "polygon 0 lies inside polygon 1"));
  // Inside and touching the outer shell along an edge.
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((0 0, 4 0, 4 4, 0 4, 0 0)))"); },
                      "polygon 1 lies inside polygon 0"));
  // The same ring twice, from another start and the other way round.
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 4, 4 0, 0 0, 0 4, 4 4)))"); },
                      "polygon 1 repeats polygon 0 (their shells are the same ring)"));
  EXPECT_TRUE(rejects(
      [] { checked("GEOMETRYCOLLECTION (POLYGON EMPTY, POLYGON ((0 0, 4 0, 0 4, 0 0)), POLYGON ((0 0, 4 0, 0 4, 0 0)))"); },
      "polygon 2 repeats polygon 1"));
  // Overlapping only where their rings pass through each other's vertices (no edges cross).
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 0, 6 2, 4 4, 3 2, 4 0)))"); },
                      "polygon 0 and polygon 1 overlap (beside the edge from (4 0) to (4 4) of polygon 0, ring 0)"));
  // An island in another part's hole is fine, one on the hole's rim too, one over the rim not.
  EXPECT_TRUE(rejects(
      [] {
        checked("MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0), (3 3, 6 3, 6 6, 3 6, 3 3)), ((2 2, 7 2, 7 7, 2 7, 2 2)))");
      },
      "lies inside polygon 0"));
}

TEST(ioParts, HolesOutsideTheirShellOrInsideEachOtherAreRefusedByName) {
  EXPECT_TRUE(rejects([] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 6 5, 6 6, 5 5))"); },
                      "polygon 0, ring 1 (a hole) lies outside its shell (polygon 0, ring 0); a hole must lie inside"));
  // A hole of one part inside another part still is not inside its own shell.
  EXPECT_TRUE(rejects(
      [] { checked("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (11 1, 12 1, 12 2, 11 1)), ((10 0, 14 0, 14 4, 10 4, 10 0)))"); },
      "polygon 0, ring 1 (a hole) lies outside its shell"));
  // Partly outside: it shares the shell's left edge from the outside.
  EXPECT_TRUE(rejects([] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (0 1, 0 2, -1 2, -1 1, 0 1))"); },
                      "polygon 0, ring 1 (a hole) lies outside its shell"));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (0 1, 2 1, 2 2, 0 2, 0 1), (0 1, 0 2, -1 2, -1 1, 0 1))"); },
      "polygon 0, ring 2 (a hole) lies outside its shell (polygon 0, ring 0)"));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 5 1, 5 2, 1 2, 1 1))"); }, "crosses"));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (4 0, 5 2, 4 4, 3 2, 4 0))"); },
      "polygon 0, ring 1 (a hole) is partly outside its shell (polygon 0, ring 0) (near the edge from "));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 8 1, 8 8, 1 8, 1 1), (2 2, 4 2, 4 4, 2 4, 2 2))"); },
      "polygon 0, ring 2 (a hole) lies inside polygon 0, ring 1 (a hole); the holes of a polygon must not overlap"));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1), (1 1, 3 1, 3 3, 1 3, 1 1))"); },
      "polygon 0, ring 2 repeats polygon 0, ring 1 (both holes)"));
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1), (1 1, 2 1, 2 2, 1 2, 1 1))"); },
      "polygon 0, ring 2 (a hole) lies inside polygon 0, ring 1 (a hole)"));
  // Overlapping where they pass through each other's vertices.
  EXPECT_TRUE(rejects(
      [] { checked("POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 4 1, 4 4, 1 4, 1 1), (4 1, 6 3, 4 4, 3 3, 4 1))"); },
      "polygon 0, ring 1 and polygon 0, ring 2 (holes) overlap (near the edge from "));
}

TEST(ioParts, RingsLoopingOverOrAgainstThemselvesAreRefused) {
  // Two loops through one vertex, turning opposite ways (a figure eight through a vertex).
  EXPECT_TRUE(rejects([] { checked("POLYGON ((0 0, 1 1, 2 2, 2 0, 1 1, 0 2, 0 0))"); },
                      "polygon 0, ring 0 (a shell) runs the wrong way around part of its area"));
  // An inner loop running the same way as the outer one covers its area twice.
  EXPECT_TRUE(rejects([] { checked("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0, 2 1, 1 2, 0 0))"); },
                      "polygon 0, ring 0 (a shell) covers some of its area twice"));
}

TEST(ioParts, CrossingEdgesNameBothEdgesByTheirEndPoints) {
  EXPECT_TRUE(rejects([] { checked("POLYGON ((0 0, 1 0, 0 1, 1 1, 0 0))"); },
                      "polygon 0, ring 0: its edge from (1 1) to (0 0) crosses its edge from (1 0) to (0 1); the edges "
                      "of a polygon may touch but must not cross"));
  EXPECT_TRUE(rejects([] { checked("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((2 2, 6 2, 6 6, 2 6, 2 2)))"); },
                      "crosses the edge from"));
}

// --- random rectangles against a cell-by-cell oracle --------------------------------------

struct Rect {
  int x0, y0, x1, y1;
  bool contains_cell(int i, int j) const { return x0 <= i && i < x1 && y0 <= j && j < y1; }
};

// With `turned`, (x, y) -> (x - y, x + y): every edge diagonal, orientation kept, areas doubled.
std::string ring_text(const Rect& r, bool reverse, int start, bool turned) {
  std::vector<std::pair<int, int>> pts{{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
  if (turned) {
    for (auto& [x, y] : pts) std::tie(x, y) = std::make_pair(x - y, x + y);
  }
  if (reverse) std::reverse(pts.begin(), pts.end());
  std::rotate(pts.begin(), pts.begin() + start, pts.end());
  pts.push_back(pts.front());
  std::string s = "(";
  for (std::size_t i = 0; i < pts.size(); ++i) {
    s += (i ? ", " : "") + std::to_string(pts[i].first) + " " + std::to_string(pts[i].second);
  }
  return s + ")";
}

// Whether a horizontal edge of one rectangle and a vertical edge of another cross at a
// point inside both (collinear overlaps and touching ends are not crossings).
bool edges_cross(const Rect& a, const Rect& b) {
  const auto cross = [](const Rect& h, const Rect& v) {
    for (const int y : {h.y0, h.y1}) {
      for (const int x : {v.x0, v.x1}) {
        if (h.x0 < x && x < h.x1 && v.y0 < y && y < v.y1) return true;
      }
    }
    return false;
  };
  return cross(a, b) || cross(b, a);
}

TEST(ioParts, RandomRectanglesAgreeWithAWindingOracleAndTheUnionArea) {
  constexpr int grid = 6;
  constexpr int cases = 4000;
  const std::uint64_t seed = 20261124;
  std::mt19937_64 rng(seed);
  std::printf("ioParts random rectangles: seed %llu, %d cases\n", static_cast<unsigned long long>(seed), cases);
  const auto rect = [&] {
    std::uniform_int_distribution<int> c(0, grid);
    Rect r{};
    do {
      r = {c(rng), c(rng), c(rng), c(rng)};
    } while (r.x0 >= r.x1 || r.y0 >= r.y1);
    return r;
  };
  int accepted_count = 0, crossing_count = 0, refused_count = 0;
  for (int n = 0; n < cases; ++n) {
    std::vector<std::vector<Rect>> parts(std::uniform_int_distribution<int>(1, 3)(rng));
    for (auto& part : parts) {
      part.push_back(rect());
      const int holes = std::uniform_int_distribution<int>(0, 2)(rng);
      for (int h = 0; h < holes; ++h) part.push_back(rect());
    }
    const bool turned = n % 2 == 1;
    std::string wkt = "MULTIPOLYGON (";
    for (std::size_t p = 0; p < parts.size(); ++p) {
      wkt += p ? ", (" : "(";
      for (std::size_t k = 0; k < parts[p].size(); ++k) {
        wkt += (k ? ", " : "") + ring_text(parts[p][k], rng() % 2 == 1, static_cast<int>(rng() % 4), turned);
      }
      wkt += ")";
    }
    wkt += ")";
    SCOPED_TRACE("seed " + std::to_string(seed) + ", case " + std::to_string(n) + ": " + wkt);

    bool crossing = false;
    std::vector<Rect> all;
    for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
    for (std::size_t i = 0; i < all.size(); ++i) {
      for (std::size_t j = i + 1; j < all.size(); ++j) crossing = crossing || edges_cross(all[i], all[j]);
    }
    bool part_bad = false;
    bool union_bad = false;
    long union_cells = 0;
    for (int i = 0; i < grid; ++i) {
      for (int j = 0; j < grid; ++j) {
        int total = 0;
        for (const auto& part : parts) {
          int w = part[0].contains_cell(i, j) ? 1 : 0;
          for (std::size_t k = 1; k < part.size(); ++k) w -= part[k].contains_cell(i, j) ? 1 : 0;
          part_bad = part_bad || (w != 0 && w != 1);
          total += w;
        }
        union_bad = union_bad || (total != 0 && total != 1);
        union_cells += total == 1;
      }
    }
    try {
      const Polygon p = checked(wkt);
      EXPECT_FALSE(crossing || part_bad || union_bad) << "accepted";
      // Accepted input is read as the union of its parts: compare exact areas.
      BooleanOptions o{Operation::union_, true, "exact"};
      o.area_exact = true;
      const BooleanOutput r = compute(p, Polygon{}, o);
      ASSERT_TRUE(r.stats.area_exact.has_value());
      EXPECT_EQ(*r.stats.area_exact, std::to_string(turned ? 2 * union_cells : union_cells));
      ++accepted_count;
    } catch (const InvalidInput& e) {
      const std::string m = e.what();
      if (crossing) {
        EXPECT_NE(m.find("crosses"), std::string::npos) << m;
        ++crossing_count;
        continue;
      }
      EXPECT_TRUE(part_bad || union_bad) << "refused: " << m;
      if (part_bad) {
        EXPECT_NE(m.find("hole"), std::string::npos) << m;  // every rectangle ring is simple
      } else {
        EXPECT_TRUE(m.find(" lies inside polygon") != std::string::npos || m.find(" repeats polygon") != std::string::npos ||
                    m.find(" overlap (") != std::string::npos)
            << m;
      }
      ++refused_count;
    }
  }
  std::printf("  accepted %d, refused for crossing edges %d, refused by winding %d\n", accepted_count, crossing_count,
              refused_count);
  EXPECT_GT(accepted_count, cases / 20);
  EXPECT_GT(refused_count, cases / 20);
}

}  // namespace
}  // namespace mk
