// Whether the edges of one polygon meet only at shared ends, without overlapping: then the
// polygon is vertex-complete as it is (no point to insert, no crossing to report), and the
// preparation's pair search needs no pair of its own edges. Decided by a plane sweep that
// stops at the first contact of any other kind [SH76]: the edges crossing the sweep line
// are kept in their order (which stays fixed while nothing meets), and only edges that
// become neighbours in that order, and a point against the edge it would lie on, are
// related. O(n log n) for n edges, whatever their bounding boxes do (a star's spikes pair
// with thousands of boxes each).
// [SH76] M. I. Shamos and D. Hoey, "Geometric intersection problems", FOCS 1976 (the first
// intersection is between neighbours on the sweep line). [MK89 §2.2] (vertex-complete)
// Preconditions: point ids follow lexicographic order; items as the pair search takes them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

#include "core/buckets.hpp"
#include "core/locator.hpp"
#include "core/pairs.hpp"
#include "core/sorting.hpp"
#include "predicates/segments.hpp"

namespace mk {

// True when no two items meet except at a shared end, at which they do not overlap
// (relate_segments_by_id says nothing of them) and no two are the same segment. False at
// the first other contact, which the pair search then finds with the rest.
template <Kernel K>
bool edges_meet_only_at_ends(const std::vector<typename K::Point>& pts, std::span<const SweepItem> items) {
  const std::size_t m = items.size();
  if (m < 2) return true;
  const auto lo = [&](int e) { return items[static_cast<std::size_t>(e)].lo; };
  const auto hi = [&](int e) { return items[static_cast<std::size_t>(e)].hi; };
  // The order on the sweep line (as the winding locator's); ties (the same segment, or
  // collinear from one start) by index, and then related as neighbours, which finds them.
  const auto is_below = [&](int a, int b) { return a != b && detail::edge_is_below<K>(pts, lo(a), hi(a), lo(b), hi(b), a < b); };
  // Whether two edges meet other than at a shared end without overlap.
  const auto meet = [&](int a, int b) {
    if (a < 0 || b < 0) return false;
    if (lo(a) == lo(b) && hi(a) == hi(b)) return true;
    const SegmentRelation rel = relate_segments_by_id<K>(pts, lo(a), hi(a), lo(b), hi(b));
    return rel.proper_crossing || rel.touches();
  };
  const std::size_t keys = pts.size();
  const Buckets by_lo = bucket_by(m, keys, [&](std::size_t e) { return lo(static_cast<int>(e)); });
  const Buckets by_hi = bucket_by(m, keys, [&](std::size_t e) { return hi(static_cast<int>(e)); });
  // The event points, in order: every item's two ends.
  std::vector<int> events;
  events.reserve(2 * m);
  for (std::size_t p = 0; p < keys; ++p) {
    if (by_lo.begin[p] != by_lo.begin[p + 1] || by_hi.begin[p] != by_hi.begin[p + 1]) events.push_back(static_cast<int>(p));
  }
  detail::BlockedOrder line;
  struct Order {
    const decltype(is_below)& below;
    bool operator()(int a, int b) const { return below(a, b); }
  };
  struct PointKey {
    int p;
  };
  struct PointOrder : Order {
    const std::vector<typename K::Point>& pts;
    std::span<const SweepItem> items;
    using Order::operator();
    // e lies below point p: p strictly above the line of e (the edges in the line run
    // across p's place in the sweep, so this is p above e).
    bool operator()(int e, const PointKey& q) const {
      const auto& it = items[static_cast<std::size_t>(e)];
      return K::orient2d(pts[it.lo], pts[it.hi], pts[q.p]) == Sign::positive;
    }
  };
  const Order order{is_below};
  const PointOrder point_order{{is_below}, pts, items};
  std::vector<int> starting;
  for (const int p : events) {
    for (int i = by_hi.begin[p]; i < by_hi.begin[p + 1]; ++i) line.erase(by_hi.order[i], order);
    // The neighbours of p's place: p on the edge above it (p is no end of an edge in the
    // line) is a point on an edge.
    const auto [below, above] = line.around(PointKey{p}, point_order);
    if (above >= 0 && K::orient2d(pts[lo(above)], pts[hi(above)], pts[p]) == Sign::zero) return false;
    starting.assign(by_lo.order.begin() + by_lo.begin[p], by_lo.order.begin() + by_lo.begin[p + 1]);
    if (starting.empty()) {
      if (meet(below, above)) return false;  // neighbours now
      continue;
    }
    sort_by_predicates<K>(starting.begin(), starting.end(), [&](int a, int b) { return is_below(a, b); });
    if (meet(below, starting.front()) || meet(starting.back(), above)) return false;
    for (std::size_t k = 0; k + 1 < starting.size(); ++k) {
      if (meet(starting[k], starting[k + 1])) return false;
    }
    for (const int e : starting) line.insert(e, order);
  }
  return true;
}

// About how many pairs of boxes of the items meet, from the sums of their sides over the
// box of all of them (boxes spread evenly): n sum(w h) + sum(w) sum(h), over W H, the sums
// taken over up to 1024 items evenly spread and scaled (a full pass over a million items
// cost more than the sweep saves elsewhere). Infinite when the items span no area (one
// line), or the sums overflow.
template <Kernel K>
double estimated_box_pairs(const std::vector<typename K::Point>& pts, std::span<const SweepItem> items)
  requires std::is_same_v<typename K::Point, Point>
{
  constexpr std::size_t kSample = 1024;
  const std::size_t step = std::max<std::size_t>(1, items.size() / kSample);
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  double swh = 0, sw = 0, sh = 0, sampled = 0;
  for (std::size_t i = 0; i < items.size(); i += step, ++sampled) {
    const Point& a = pts[static_cast<std::size_t>(items[i].lo)];
    const Point& b = pts[static_cast<std::size_t>(items[i].hi)];
    const double w = std::abs(b.x - a.x), h = std::abs(b.y - a.y);
    swh += w * h, sw += w, sh += h;
    x0 = std::min(x0, a.x), x1 = std::max(x1, b.x);
    y0 = std::min({y0, a.y, b.y}), y1 = std::max({y1, a.y, b.y});
  }
  const double n = static_cast<double>(items.size());
  const double scale = n / sampled;
  const double area = (x1 - x0) * (y1 - y0);
  const double pairs = (n * swh * scale + sw * sh * scale * scale) / area;
  return std::isfinite(pairs) && area > 0 ? pairs : HUGE_VAL;
}

// The same estimate for the boxes the pair search pairs: those of its chains, runs of
// consecutive edges of one ring that go the same way (detail::Chain). Sampled as above: the
// chain through each of up to 1024 evenly spread items, each counted 1 / its length times,
// so that long chains are not counted more often for being sampled more often. Where the
// edges' boxes are small but the chains' are not (the chains of nested rings: quarters
// of each ring, whose boxes all nest around one centre), this sees the pairs the search
// will meet.
template <Kernel K>
double estimated_chain_pairs(const std::vector<typename K::Point>& pts, std::span<const SweepItem> items)
  requires std::is_same_v<typename K::Point, Point>
{
  constexpr std::size_t kSample = 1024;
  const std::size_t n = items.size();
  if (n == 0) return 0;
  const std::size_t step = std::max<std::size_t>(1, n / kSample);
  const auto course = [&](std::size_t i) {
    const Point& a = pts[static_cast<std::size_t>(items[i].lo)];
    const Point& b = pts[static_cast<std::size_t>(items[i].hi)];
    return (items[i].forward ? 1 : 0) | (b.y > a.y ? 2 : (b.y < a.y ? 4 : 0)) | (a.x == b.x ? 8 : 0);
  };
  // Item i joins the chain of item i - 1.
  const auto joins = [&](std::size_t i) {
    return items[i].continues && items[i].group == items[i - 1].group && course(i) == course(i - 1);
  };
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  double chains = 0, swh = 0, sw = 0, sh = 0, sampled = 0;
  for (std::size_t s = 0; s * step < n; ++s, ++sampled) {
    // A place in each stretch of `step` items, varied from stretch to stretch (a fixed one
    // would see only one side of every square when step is a multiple of 4).
    const std::size_t i = std::min(n - 1, s * step + (s * 2654435761u) % step);
    std::size_t first = i, last = i + 1;
    while (first > 0 && last - first < static_cast<std::size_t>(detail::kMaxChain) && joins(first)) --first;
    while (last < n && last - first < static_cast<std::size_t>(detail::kMaxChain) && joins(last)) ++last;
    double bx0 = HUGE_VAL, bx1 = -HUGE_VAL, by0 = HUGE_VAL, by1 = -HUGE_VAL;
    for (const std::size_t k : {first, last - 1}) {
      for (const int id : {items[k].lo, items[k].hi}) {
        const Point& q = pts[static_cast<std::size_t>(id)];
        bx0 = std::min(bx0, q.x), bx1 = std::max(bx1, q.x), by0 = std::min(by0, q.y), by1 = std::max(by1, q.y);
      }
    }
    const double weight = 1.0 / static_cast<double>(last - first);
    const double w = bx1 - bx0, h = by1 - by0;
    chains += weight, swh += weight * w * h, sw += weight * w, sh += weight * h;
    x0 = std::min(x0, bx0), x1 = std::max(x1, bx1), y0 = std::min(y0, by0), y1 = std::max(y1, by1);
  }
  const double scale = static_cast<double>(n) / sampled;
  const double area = (x1 - x0) * (y1 - y0);
  const double pairs = (chains * scale * swh * scale + sw * sh * scale * scale) / area;
  return std::isfinite(pairs) && area > 0 ? pairs : HUGE_VAL;
}

}  // namespace mk
