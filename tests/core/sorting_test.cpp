// Sorting points of doubles by their bits (sort_points_lexicographic, the point numbering's
// radix sort) against comparison sorts: a plain stable sort of doubles, and the rational
// kernel's numbering, which compares GMP rationals.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/prepare.hpp"
#include "core/sorting.hpp"

namespace mk {
namespace {

// Doubles of every kind the sort must order: small integers and halves (most key bytes
// shared), both zeros, subnormals, the extremes, infinities and wide random magnitudes.
double any_double(std::mt19937_64& rng) {
  switch (rng() % 8) {
    case 0: return static_cast<double>(static_cast<int>(rng() % 21) - 10);
    case 1: return static_cast<double>(static_cast<int>(rng() % 41) - 20) / 2;
    case 2: return (rng() & 1) ? -0.0 : 0.0;
    case 3: return ((rng() & 1) ? -1.0 : 1.0) * std::numeric_limits<double>::denorm_min() * static_cast<double>(rng() % 5 + 1);
    case 4: {
      constexpr double kEdges[] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::min(), -std::numeric_limits<double>::min()};
      return kEdges[rng() % 6];
    }
    default: {
      const double m = std::uniform_real_distribution<double>(-1, 1)(rng);
      return std::ldexp(m, static_cast<int>(rng() % 2001) - 1000);
    }
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Every size (below and above the radix sort's threshold), every kind of double, points
// repeated: the same sequence as a stable comparison sort of doubles, payload and zero signs
// included (equal points, -0 and +0 among them, keep the order they came in).
TEST(SortPointsLexicographic, EqualsAStableComparisonSortOnEveryKindOfDouble) {
  std::mt19937_64 rng(2026);
  for (const std::size_t n : {0, 1, 2, 3, 255, 256, 257, 1000, 20000}) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<std::pair<Point, int>> items;
      for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && rng() % 4 == 0) {
          Point again = items[rng() % i].first;  // a repeated point, sometimes with the other zero
          if (again.x == 0 && rng() % 2) again.x = -again.x;
          items.emplace_back(again, static_cast<int>(i));
        } else {
          items.emplace_back(Point{any_double(rng), any_double(rng)}, static_cast<int>(i));
        }
      }
      auto expected = items;
      std::stable_sort(expected.begin(), expected.end(), [](const auto& u, const auto& w) {
        return u.first.x != w.first.x ? u.first.x < w.first.x : u.first.y < w.first.y;
      });
      sort_points_lexicographic(std::span(items));
      ASSERT_EQ(items.size(), expected.size());
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(same_bits(items[i].first.x, expected[i].first.x) && same_bits(items[i].first.y, expected[i].first.y) &&
                    items[i].second == expected[i].second)
            << "n " << n << " trial " << trial << " position " << i;
      }
    }
  }
}

// Only the bytes that differ are sorted by: keys that differ in their highest byte alone,
// in their lowest byte alone, and in x only or y only.
TEST(SortPointsLexicographic, OrdersKeysThatDifferInOneByteOnly) {
  std::vector<std::pair<Point, int>> items;
  for (int i = 0; i < 600; ++i) {
    const double low = std::nextafter(1.0, 2.0 + i);  // 1 and 1 + ulp (lowest byte)
    const double x = (i % 3 == 0) ? -low : (i % 3 == 1 ? 0x1p900 : low);
    const double y = std::ldexp(1.0, (i * 7919) % 600 - 300);  // exponent bytes only
    items.emplace_back(Point{x, y}, i);
  }
  auto expected = items;
  std::stable_sort(expected.begin(), expected.end(), [](const auto& u, const auto& w) {
    return u.first.x != w.first.x ? u.first.x < w.first.x : u.first.y < w.first.y;
  });
  sort_points_lexicographic(std::span(items));
  EXPECT_EQ(items, expected);
}

// The point numbering of many small rings (too many monotone runs to merge, so the points
// are sorted): the exact kernel's, sorted by the doubles' bits, gives the same points in the
// same order as the rational kernel's, sorted by comparing GMP rationals, on one thread and two.
TEST(SortPointsLexicographic, NumberingEqualsTheRationalKernelsOnWildCoordinates) {
  std::mt19937_64 rng(11);
  std::array<Polygon, 2> poly;
  for (auto& p : poly) {
    for (int r = 0; r < 3000; ++r) {
      const Point c{any_double(rng), any_double(rng)};
      if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
      p.rings.push_back({c, {c.x, any_double(rng)}, {any_double(rng), c.y}});
      for (Point& q : p.rings.back()) {
        if (!std::isfinite(q.x)) q.x = c.x;
        if (!std::isfinite(q.y)) q.y = c.y;
      }
    }
  }
  const auto number = [&]<class K>(K, unsigned threads) {
    const std::array<BasicPolygon<typename K::Point>, 2> in = {to_kernel_polygon<K>(poly[0]), to_kernel_polygon<K>(poly[1])};
    std::size_t total = 0;
    for (const auto& p : in) {
      for (const auto& ring : p.rings) total += ring.size();
    }
    std::pair<std::vector<typename K::Point>, std::vector<int>> out;  // points, x-ranks
    std::vector<int> id_of(total);
    detail::number_points<K>({&in[0], &in[1]}, total, threads, out.first, out.second, id_of);
    return std::pair(std::move(out), std::move(id_of));
  };
  using R = RationalKernel;
  const auto [rational, rational_ids] = number(R{}, 1);
  ASSERT_GT(rational.first.size(), 10000U);
  for (const unsigned threads : {1u, 2u}) {
    const auto [exact, exact_ids] = number(ExactKernel{}, threads);
    ASSERT_EQ(exact.first.size(), rational.first.size());
    EXPECT_EQ(exact.second, rational.second);
    EXPECT_EQ(exact_ids, rational_ids);
    for (std::size_t i = 0; i < exact.first.size(); ++i) {
      ASSERT_EQ(R::point(exact.first[i]), rational.first[i]) << i;
    }
  }
}

}  // namespace
}  // namespace mk
