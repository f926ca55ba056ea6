// Input preparation: points touching their own polygon's edges are inserted into exactly the
// edges they touch, ring by ring, and rings nobody touches are left as they were.
// [MK89 §2.2] [MK89 §3.3 end]
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/prepare.hpp"

namespace mk {
namespace {

template <class K>
int id_of(const Arrangement<K>& arr, double x, double y) {
  const auto q = K::point(Point{x, y});
  for (int i = 0; i < arr.num_points(); ++i) {
    if (compare_xy<K>(arr.points[i], q) == Sign::zero) return i;
  }
  return -1;
}

// The cycle of polygon p that holds all of `ids` (as point ids), or nullptr.
const std::vector<int>* cycle_with(const PreparedPolygon& p, const std::vector<int>& ids) {
  for (const auto& c : p.cycles) {
    if (std::all_of(ids.begin(), ids.end(), [&](int id) { return std::find(c.begin(), c.end(), id) != c.end(); })) {
      return &c;
    }
  }
  return nullptr;
}

// True when b follows a in the cycle (cyclically).
bool follows(const std::vector<int>& c, int a, int b) {
  const auto it = std::find(c.begin(), c.end(), a);
  if (it == c.end()) return false;
  return *(it + 1 == c.end() ? c.begin() : it + 1) == b;
}

template <class K>
void check_touching_rings() {
  // Ring 0: untouched. Ring 1: a square whose bottom edge ring 2 touches at (2, 0). Ring 3: a
  // square whose top edge ring 4 touches at (32, 4); ring 4 also has a vertex nobody touches.
  const Polygon a{{
                      {{20, 0}, {22, 0}, {22, 2}, {20, 2}},
                      {{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                      {{2, 0}, {3, 2}, {1, 2}},
                      {{30, 0}, {34, 0}, {34, 4}, {30, 4}},
                      {{32, 4}, {31, 2}, {33, 2}},
                  },
                  PolygonType::island};
  const Polygon b{{{{100, 100}, {101, 100}, {101, 101}}}, PolygonType::island};
  const Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b));
  const PreparedPolygon& p = arr.polygon[0];
  ASSERT_EQ(p.cycles.size(), 5u);
  std::size_t total = 0;
  for (const auto& c : p.cycles) total += c.size();
  EXPECT_EQ(total, 4u + 5u + 3u + 5u + 3u);  // one point inserted into rings 1 and 3

  const auto id = [&](double x, double y) { return id_of(arr, x, y); };
  const auto* ring0 = cycle_with(p, {id(20, 0), id(22, 0), id(22, 2), id(20, 2)});
  ASSERT_NE(ring0, nullptr);
  EXPECT_EQ(ring0->size(), 4u);
  const auto* ring1 = cycle_with(p, {id(0, 0), id(4, 0), id(2, 0)});
  ASSERT_NE(ring1, nullptr);
  EXPECT_TRUE(follows(*ring1, id(0, 0), id(2, 0)));
  EXPECT_TRUE(follows(*ring1, id(2, 0), id(4, 0)));
  const auto* ring3 = cycle_with(p, {id(34, 4), id(30, 4), id(32, 4)});
  ASSERT_NE(ring3, nullptr);
  EXPECT_TRUE(follows(*ring3, id(34, 4), id(32, 4)));
  EXPECT_TRUE(follows(*ring3, id(32, 4), id(30, 4)));
  EXPECT_EQ(cycle_with(p, {id(2, 0), id(3, 2), id(1, 2)})->size(), 3u);
  EXPECT_EQ(cycle_with(p, {id(32, 4), id(31, 2), id(33, 2)})->size(), 3u);
}

TEST(Prepare, TouchingPointsAreInsertedIntoTheEdgesTheyTouchOnly) {
  check_touching_rings<RationalKernel>();
  check_touching_rings<ExactKernel>();
}

TEST(Prepare, SeveralPointsOnOneEdgeAreInsertedInOrderAlongIt) {
  // Two triangles touch the square's top edge, which runs from (4, 4) to (0, 4).
  const Polygon a{{
                      {{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                      {{1, 4}, {1.5, 3}, {0.5, 3}},
                      {{3, 4}, {3.5, 3}, {2.5, 3}},
                  },
                  PolygonType::island};
  const Polygon b{{{{100, 100}, {101, 100}, {101, 101}}}, PolygonType::island};
  using K = RationalKernel;
  const Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(b));
  const auto id = [&](double x, double y) { return id_of(arr, x, y); };
  const auto* outer = cycle_with(arr.polygon[0], {id(0, 0), id(4, 4), id(1, 4), id(3, 4)});
  ASSERT_NE(outer, nullptr);
  EXPECT_EQ(outer->size(), 6u);
  EXPECT_TRUE(follows(*outer, id(4, 4), id(3, 4)));
  EXPECT_TRUE(follows(*outer, id(3, 4), id(1, 4)));
  EXPECT_TRUE(follows(*outer, id(1, 4), id(0, 4)));
}

// A ring meeting itself is split into cycles at the point it passes twice, whether that
// point is an input vertex given twice or a vertex touching the ring's own edge (inserted
// there; every input point distinct). Rings of distinct points, nothing inserted, stay as
// they are.
template <class K>
void check_rings_meeting_themselves() {
  const Polygon a{{
                      {{0, 0}, {4, 0}, {4, 4}, {3, 4}, {2, 0}, {1, 4}, {0, 4}},  // touches its bottom edge
                  },
                  PolygonType::island};
  const Polygon b{{{{10, 0}, {12, 2}, {14, 0}, {14, 4}, {12, 2}, {10, 4}}}, PolygonType::island};  // a figure 8
  const Polygon c{{{{20, 0}, {24, 0}, {24, 4}, {20, 4}}, {{21, 1}, {21, 3}, {23, 3}}}, PolygonType::island};
  {
    const Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(a), to_kernel_polygon<K>(c));
    const auto id = [&](double x, double y) { return id_of(arr, x, y); };
    const PreparedPolygon& p = arr.polygon[0];
    ASSERT_EQ(p.cycles.size(), 2u);
    const auto* right = cycle_with(p, {id(2, 0), id(4, 0), id(4, 4), id(3, 4)});
    const auto* left = cycle_with(p, {id(0, 0), id(2, 0), id(1, 4), id(0, 4)});
    ASSERT_NE(right, nullptr);
    ASSERT_NE(left, nullptr);
    EXPECT_EQ(right->size(), 4u);
    EXPECT_EQ(left->size(), 4u);
    // c's rings hold distinct points and nothing touches them: its cycles are its rings.
    const PreparedPolygon& q = arr.polygon[1];
    ASSERT_EQ(q.cycles.size(), 2u);
    EXPECT_EQ(q.cycles[0].size(), 4u);
    EXPECT_EQ(q.cycles[1].size(), 3u);
    EXPECT_EQ(q.origins[1].ring, 1);
  }
  {
    const Arrangement<K> arr = prepare<K>(to_kernel_polygon<K>(c), to_kernel_polygon<K>(b));
    const auto id = [&](double x, double y) { return id_of(arr, x, y); };
    const PreparedPolygon& p = arr.polygon[1];
    ASSERT_EQ(p.cycles.size(), 2u);
    EXPECT_NE(cycle_with(p, {id(12, 2), id(14, 0), id(14, 4)}), nullptr);
    EXPECT_NE(cycle_with(p, {id(10, 0), id(12, 2), id(10, 4)}), nullptr);
  }
}

TEST(Prepare, RingsMeetingThemselvesAreSplitAndOthersKept) {
  check_rings_meeting_themselves<RationalKernel>();
  check_rings_meeting_themselves<ExactKernel>();
}

// The numbering by merged monotone runs equals numbering by a plain sort: the same distinct
// points in lexicographic order, and every input vertex mapped to its point. Inputs mix
// ascending and descending runs, repeated points (within a ring, across rings and across
// polygons), equal x with different y, and -0 next to +0.
TEST(Prepare, NumberingByMergedRunsEqualsNumberingBySort) {
  using K = ExactKernel;
  const std::uint64_t seed = 20261123;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> coord(-6, 6);
  std::uniform_int_distribution<int> len(1, 12);
  std::uniform_int_distribution<int> rings(1, 3);
  for (int iter = 0; iter < 500; ++iter) {
    std::array<Polygon, 2> poly;
    std::vector<Point> flat;
    for (auto& p : poly) {
      for (int r = rings(rng); r > 0; --r) {
        Ring ring;
        for (int k = len(rng); k > 0; --k) {
          const double x = coord(rng) / 2.0;
          ring.push_back({x == 0 && (rng() & 1) ? -0.0 : x, static_cast<double>(coord(rng))});
        }
        // Sort some rings into long runs, ascending or descending.
        if (rng() % 3 == 0) {
          std::sort(ring.begin(), ring.end(), [](const Point& u, const Point& w) {
            return compare_xy<K>(u, w) == Sign::negative;
          });
          if (rng() & 1) std::reverse(ring.begin(), ring.end());
        }
        flat.insert(flat.end(), ring.begin(), ring.end());
        p.rings.push_back(std::move(ring));
      }
    }
    std::vector<Point> expected = flat;
    std::sort(expected.begin(), expected.end(),
              [](const Point& u, const Point& w) { return compare_xy<K>(u, w) == Sign::negative; });
    expected.erase(std::unique(expected.begin(), expected.end(),
                               [](const Point& u, const Point& w) { return compare_xy<K>(u, w) == Sign::zero; }),
                   expected.end());
    const std::array<const Polygon*, 2> in{&poly[0], &poly[1]};
    {
      std::vector<Point> points;
      std::vector<int> x_rank;
      std::vector<int> id_of(flat.size(), -1);
      ASSERT_TRUE(detail::number_points_by_runs<K>(in, 1000, points, x_rank, id_of));
      ASSERT_EQ(points.size(), expected.size()) << "iter " << iter;
      ASSERT_EQ(x_rank.size(), expected.size()) << "iter " << iter;
      int rank = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(compare_xy<K>(points[i], expected[i]), Sign::zero) << "iter " << iter << " point " << i;
        if (i > 0 && expected[i - 1].x != expected[i].x) ++rank;
        EXPECT_EQ(x_rank[i], rank) << "iter " << iter << " point " << i;
      }
      for (std::size_t k = 0; k < flat.size(); ++k) {
        ASSERT_GE(id_of[k], 0) << "iter " << iter << " vertex " << k;
        EXPECT_EQ(compare_xy<K>(points[id_of[k]], flat[k]), Sign::zero)
            << "iter " << iter << " vertex " << k;
      }
    }
    // With too few runs allowed it declines and leaves its outputs alone.
    std::vector<Point> untouched;
    std::vector<int> untouched_ranks;
    std::vector<int> ids(flat.size(), -1);
    EXPECT_FALSE(detail::number_points_by_runs<K>(in, 0, untouched, untouched_ranks, ids));
    EXPECT_TRUE(untouched.empty());
    EXPECT_TRUE(untouched_ranks.empty());
    EXPECT_TRUE(std::all_of(ids.begin(), ids.end(), [](int v) { return v == -1; }));
  }
}

// Merging the runs in two halves on two threads (enough points for it) gives what one
// thread gives, bit for bit: the points, their x-ranks and every vertex's id. Coordinates
// from a small grid repeat points in both halves (the upper half's ids are then moved down)
// and put equal x on both sides of the cut; from a wide range nothing repeats (its ids are
// right as first written). Zeros of both signs throughout.
TEST(Prepare, NumberingByRunsOnTwoThreadsEqualsOneThread) {
  using K = ExactKernel;
  for (const int spread : {40, 300, 1 << 30}) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(spread));
    std::uniform_int_distribution<int> coord(-spread, spread);
    std::array<Polygon, 2> poly;
    std::vector<Point> flat;
    for (auto& p : poly) {
      for (int r = 0; r < 12; ++r) {
        Ring ring;
        for (int k = 0; k < 6000 + r * 200; ++k) {
          const double x = coord(rng) / 4.0;
          const double y = coord(rng);
          ring.push_back({x == 0 && (rng() & 1) ? -0.0 : x, y == 0 && (rng() & 1) ? -0.0 : y});
        }
        // One run each: sorted, without repeats in a row (a descending run is strict).
        std::sort(ring.begin(), ring.end(), [](const Point& u, const Point& w) { return compare_xy<K>(u, w) == Sign::negative; });
        ring.erase(std::unique(ring.begin(), ring.end(), [](const Point& u, const Point& w) { return compare_xy<K>(u, w) == Sign::zero; }),
                   ring.end());
        if (rng() & 1) std::reverse(ring.begin(), ring.end());
        flat.insert(flat.end(), ring.begin(), ring.end());
        p.rings.push_back(std::move(ring));
      }
    }
    ASSERT_GE(flat.size(), static_cast<std::size_t>(detail::kHalvesFrom));
    const std::array<const Polygon*, 2> in{&poly[0], &poly[1]};
    std::array<std::vector<Point>, 2> points;
    std::array<std::vector<int>, 2> x_rank;
    std::array<std::vector<int>, 2> id_of{std::vector<int>(flat.size(), -1), std::vector<int>(flat.size(), -1)};
    for (unsigned t = 0; t < 2; ++t) {
      ASSERT_TRUE(detail::number_points_by_runs<K>(in, 1000, points[t], x_rank[t], id_of[t], t + 1));
    }
    ASSERT_EQ(points[0].size(), points[1].size()) << spread;
    for (std::size_t i = 0; i < points[0].size(); ++i) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(points[0][i].x), std::bit_cast<std::uint64_t>(points[1][i].x)) << spread << " " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(points[0][i].y), std::bit_cast<std::uint64_t>(points[1][i].y)) << spread << " " << i;
    }
    EXPECT_EQ(x_rank[0], x_rank[1]) << spread;
    EXPECT_EQ(id_of[0], id_of[1]) << spread;
    // And both are right: sorted, distinct, x-ranks counted, every vertex on its point.
    for (std::size_t i = 1; i < points[1].size(); ++i) {
      ASSERT_EQ(compare_xy<K>(points[1][i - 1], points[1][i]), Sign::negative) << spread << " " << i;
      ASSERT_EQ(x_rank[1][i], x_rank[1][i - 1] + (points[1][i - 1].x != points[1][i].x ? 1 : 0)) << spread << " " << i;
    }
    for (std::size_t k = 0; k < flat.size(); ++k) {
      ASSERT_EQ(compare_xy<K>(points[1][id_of[1][k]], flat[k]), Sign::zero) << spread << " " << k;
    }
    if (spread == 40) {
      EXPECT_LT(points[1].size(), flat.size() / 2);  // the small grid repeats most points across rings
    }
    if (spread == (1 << 30)) {
      EXPECT_GT(points[1].size(), flat.size() - 100);  // the wide range almost none
    }
  }
}

// Many small rings (too many runs to merge: the points are sorted, on two threads when there
// are enough), the same corners repeated with zeros of both signs: the same ids, x-ranks and
// points, bit for bit, on one thread and on two, and each point kept with +0 wherever one of
// its copies has +0.
TEST(Prepare, SortedNumberingIsTheSameOnAnyNumberOfThreadsWithSignedZeros) {
  using K = ExactKernel;
  std::mt19937 rng(7);
  const auto zero_or = [&](double v) { return v == 0 && (rng() & 1) ? -0.0 : v; };
  std::array<Polygon, 2> poly;
  for (auto& p : poly) {
    for (int r = 0; r < 6000; ++r) {
      const double x = static_cast<double>(static_cast<int>(rng() % 41) - 20);
      const double y = static_cast<double>(static_cast<int>(rng() % 41) - 20);
      p.rings.push_back({{zero_or(x), zero_or(y)}, {zero_or(x + 1), zero_or(y)}, {zero_or(x + 1), zero_or(y + 1)}});
    }
  }
  // Per distinct point: whether some copy has +0 in x, in y.
  std::vector<std::pair<Point, std::array<bool, 2>>> seen;
  for (const auto& p : poly) {
    for (const auto& ring : p.rings) {
      for (const Point& q : ring) {
        auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& e) { return e.first.x == q.x && e.first.y == q.y; });
        if (it == seen.end()) it = seen.insert(seen.end(), {q, {false, false}});
        it->second[0] = it->second[0] || (q.x == 0 && !std::signbit(q.x));
        it->second[1] = it->second[1] || (q.y == 0 && !std::signbit(q.y));
      }
    }
  }
  ASSERT_GE(3 * 2 * 6000, static_cast<int>(kParallelWork));
  const Arrangement<K> one = prepare<K>(poly[0], poly[1], PairSearch::sweep, 1);
  const Arrangement<K> two = prepare<K>(poly[0], poly[1], PairSearch::sweep, 2);
  ASSERT_EQ(one.points.size(), seen.size());
  ASSERT_EQ(two.points.size(), seen.size());
  EXPECT_EQ(one.x_rank, two.x_rank);
  for (std::size_t i = 0; i < one.points.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(one.points[i].x), std::bit_cast<std::uint64_t>(two.points[i].x)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(one.points[i].y), std::bit_cast<std::uint64_t>(two.points[i].y)) << i;
    const Point& q = one.points[i];
    const auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& e) { return e.first.x == q.x && e.first.y == q.y; });
    ASSERT_NE(it, seen.end());
    if (q.x == 0) {
      EXPECT_EQ(!std::signbit(q.x), it->second[0]) << i;
    }
    if (q.y == 0) {
      EXPECT_EQ(!std::signbit(q.y), it->second[1]) << i;
    }
  }
  for (int p = 0; p < 2; ++p) EXPECT_EQ(one.polygon[p].cycles, two.polygon[p].cycles);
}

}  // namespace
}  // namespace mk
