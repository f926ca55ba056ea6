// Sorting for the core: by a kernel's predicates (sort_by_predicates), and points of doubles
// by their bits (sort_points_lexicographic, the point numbering's radix sort).
//
// By a kernel's predicates: an exact kernel's comparisons are consistent and
// std::sort serves; an inexact kernel's may not be (a naive kernel's products overflow to
// infinity or NaN near 1e300, rounded crossings compare inconsistently), and std::sort's
// unguarded insertion then runs past the range (a crash seen at 1e300 with kernel `double`).
// A heap sort's index arithmetic stays inside the range whatever the comparison answers: the
// order may be wrong, as the kernel's answers are, but nothing is read or written outside.
// [BRIEF §8] (bad input: never a crash)
// Preconditions: none on `less` for inexact kernels; a strict weak order for exact ones.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/kernel.hpp"
#include "kernel/point.hpp"

namespace mk {

template <Kernel K, class It, class Less>
void sort_by_predicates(It first, It last, Less&& less) {
  if constexpr (K::is_exact) {
    std::sort(first, last, less);
  } else {
    std::make_heap(first, last, less);
    std::sort_heap(first, last, less);
  }
}

namespace detail {

// A double's bits as an unsigned key in the double's order: -0 and +0 give one key, negative
// numbers' bits are inverted, positive numbers' sign bit is set. (NaN never reaches here: the
// readers and the library refuse it.)
inline std::uint64_t order_key(double v) {
  const auto u = std::bit_cast<std::uint64_t>(v + 0.0);  // -0 + 0 is +0
  return (u >> 63) != 0 ? ~u : u | (std::uint64_t{1} << 63);
}

}  // namespace detail

// Sorts `items` by their points in lexicographic order (x, then y, compared as doubles: -0
// equals +0), equal points in the order they came. A least-significant-digit radix sort over
// the eight bytes of each coordinate's order key, y's first, each pass a stable counting
// sort by one byte; a byte that every key shares is not sorted by (small integers share
// most of theirs), so it costs one counting pass and at most 16 moves per item, where a
// comparison sort makes log2(n) comparisons per item that branch unpredictably.
template <class T>
void sort_points_lexicographic(std::span<std::pair<Point, T>> items) {
  const std::size_t n = items.size();
  if (n < 256) {
    std::stable_sort(items.begin(), items.end(), [](const auto& u, const auto& w) {
      return u.first.x != w.first.x ? u.first.x < w.first.x : u.first.y < w.first.y;
    });
    return;
  }
  // count[d][b]: keys whose byte d is b; digits 0-7 are y's bytes from the lowest, 8-15 x's.
  std::vector<std::array<std::uint32_t, 256>> count(16, std::array<std::uint32_t, 256>{});
  for (const auto& item : items) {
    const std::uint64_t ky = detail::order_key(item.first.y);
    const std::uint64_t kx = detail::order_key(item.first.x);
    for (std::size_t b = 0; b < 8; ++b) {
      ++count[b][(ky >> (8 * b)) & 0xff];
      ++count[8 + b][(kx >> (8 * b)) & 0xff];
    }
  }
  std::vector<std::pair<Point, T>> other(n);
  std::span<std::pair<Point, T>> from = items;
  std::span<std::pair<Point, T>> to = other;
  for (std::size_t d = 0; d < 16; ++d) {
    auto& c = count[d];
    if (std::find(c.begin(), c.end(), static_cast<std::uint32_t>(n)) != c.end()) continue;  // shared byte
    std::uint32_t start = 0;
    for (auto& k : c) start += std::exchange(k, start);
    const std::size_t shift = 8 * (d % 8);
    for (const auto& item : from) {
      const std::uint64_t key = detail::order_key(d < 8 ? item.first.y : item.first.x);
      to[c[(key >> shift) & 0xff]++] = item;
    }
    std::swap(from, to);
  }
  if (from.data() != items.data()) std::copy(from.begin(), from.end(), items.begin());
}

}  // namespace mk
