// The pairs of edges, one of each polygon, that meet, found by a plane sweep whose cost
// follows the number of such pairs, not the number of boxes that overlap: O((n + k) log n)
// for n edges and k meeting pairs. The pair search by boxes (core/pairs.hpp) pairs every
// two edges whose boxes overlap; where long slanted edges lie close to many others without
// meeting them (contour-like nested rings whose segments are much longer than the rings'
// spacing), that is quadratic in n however few edges meet.
//
// The sweep is Bentley and Ottmann's [BO79] for two sets of edges ("red" A, "blue" B) each
// of which meets itself only at shared ends, as each polygon does once its own sweep found
// it so (core/clean_edges.hpp) [MS88]: then only a red and a blue edge can cross, a proper
// crossing has exactly two edges through it and never lies on an input point, and every
// other contact is at an input point. The edges that meet the sweep line are kept in their
// order along it; two edges that cross are neighbours just before their crossing, which is
// an event where they trade places; at a point, every edge through it (ending, starting,
// passing, vertical) is related to every other of the other polygon. Only orientations of
// input points decide the order and which neighbours cross ahead; crossings are
// constructed (as the kernel's vertices) only to order the events.
// [BO79] J. L. Bentley and T. A. Ottmann, "Algorithms for reporting and counting geometric
// intersections", IEEE Trans. Computers C-28(9), 1979. [MS88] H. G. Mairson and J. Stolfi,
// "Reporting and counting intersections between two sets of line segments", NATO ASI F40,
// 1988 (red/blue segments, each set free of crossings). [BKOS08 §2.1] (the status order
// just below and after an event point)
// Preconditions: point ids follow lexicographic order; items as the pair search takes them
// (lo < hi); the items of each group meet only at shared ends (edges_meet_only_at_ends);
// an exact kernel over double points.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory_resource>
#include <set>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/buckets.hpp"
#include "core/clean_edges.hpp"
#include "core/pairs.hpp"
#include "core/parallel.hpp"
#include "kernel/kernel.hpp"

namespace mk {

namespace detail {

// An edge on the sweep line, with copies of its ends.
struct RedBlueEntry {
  int edge;
  Point lo, hi;
};

// The order along the sweep line just after the current event point p. An edge is only
// ever compared with one being inserted at p, which passes through p or starts there: an
// edge not through p lies wholly above or below p on the line; two through p are ordered
// by where they go from p (collinear ones by index).
struct RedBlueProbe {
  const Point* p;
};
struct RedBlueContext {
  const Point* p = nullptr;
  int fresh = -1;  // the edge being inserted
};
template <class K>
struct RedBlueBelow {
  using is_transparent = void;
  const RedBlueContext* ctx;
  // Sign of s (through ctx->p) against t: positive when s lies above t.
  int fresh_against(const RedBlueEntry& s, const RedBlueEntry& t) const {
    const Point& p = *ctx->p;
    Sign o = K::orient2d(t.lo, t.hi, p);
    if (o == Sign::zero) o = K::orient2d(p, t.hi, s.hi);
    if (o == Sign::zero) return s.edge < t.edge ? -1 : 1;
    return o == Sign::positive ? 1 : -1;
  }
  bool operator()(const RedBlueEntry& a, const RedBlueEntry& b) const {
    if (a.edge == ctx->fresh) return fresh_against(a, b) < 0;
    if (b.edge == ctx->fresh) return fresh_against(b, a) > 0;
    throw std::logic_error("red_blue_meeting_pairs: two edges on the line compared");
  }
  bool operator()(const RedBlueEntry& t, RedBlueProbe q) const { return K::orient2d(t.lo, t.hi, *q.p) == Sign::positive; }
  bool operator()(RedBlueProbe q, const RedBlueEntry& t) const { return K::orient2d(t.lo, t.hi, *q.p) == Sign::negative; }
};

}  // namespace detail

// Every pair (i, j) of items, i of group 0 and j of group 1, that have a point in common
// other than an end of both (they cross, an end of one lies on the other, or they overlap),
// each once, in increasing order. Left out: two that meet only at a shared end, and the same
// segment in both groups; step 3's relation of such a pair says nothing
// (relate_edges_across).
template <Kernel K>
  requires(std::is_same_v<typename K::Point, Point> && K::is_exact)
std::vector<std::pair<int, int>> red_blue_meeting_pairs(const std::vector<Point>& pts, std::span<const SweepItem> items) {
  using Entry = detail::RedBlueEntry;
  const std::size_t m = items.size();
  std::vector<std::pair<int, int>> out;
  const auto in_group = [&](int g) { return std::any_of(items.begin(), items.end(), [&](const SweepItem& it) { return it.group == g; }); };
  if (m < 2 || !in_group(0) || !in_group(1)) return out;
  const auto group = [&](int e) { return items[static_cast<std::size_t>(e)].group; };
  const auto lo = [&](int e) { return items[static_cast<std::size_t>(e)].lo; };
  const auto hi = [&](int e) { return items[static_cast<std::size_t>(e)].hi; };
  const auto vertical = [&](int e) { return pts[static_cast<std::size_t>(lo(e))].x == pts[static_cast<std::size_t>(hi(e))].x; };
  const auto report = [&](int a, int b) {
    if (group(a) == group(b)) return;
    out.emplace_back(std::min(a, b), std::max(a, b));
  };
  const auto side = [](const Entry& t, const Point& q) { return K::orient2d(t.lo, t.hi, q); };  // positive: q above t

  using Probe = detail::RedBlueProbe;
  detail::RedBlueContext ctx;
  std::pmr::unsynchronized_pool_resource arena;
  using Line = std::pmr::set<Entry, detail::RedBlueBelow<K>>;
  Line line(detail::RedBlueBelow<K>{&ctx}, &arena);
  using It = typename Line::iterator;
  std::vector<It> where(m);
  std::vector<char> on_line(m, 0);

  // Crossings ahead, earliest first.
  struct Crossing {
    typename K::Vertex at;
    int below, above;  // the edges, in their order before the crossing
  };
  std::vector<Crossing> heap;
  const auto later = [](const Crossing& u, const Crossing& v) { return K::compare_vertices(u.at, v.at) == Sign::positive; };
  // Neighbours a below b just after the current event: do they cross ahead? Then the edge
  // that ends first has its end on the other side of the other's line.
  const auto watch = [&](It ia, It ib) {
    const Entry& a = *ia;
    const Entry& b = *ib;
    if (group(a.edge) == group(b.edge)) return;
    const int ha = hi(a.edge), hb = hi(b.edge);
    if (ha == hb) return;  // they meet at the shared end: an event point
    const bool crosses = ha < hb ? side(b, a.hi) == Sign::positive : side(a, b.hi) == Sign::negative;
    if (!crosses) return;
    heap.push_back({K::crossing(a.lo, a.hi, b.lo, b.hi), a.edge, b.edge});
    std::push_heap(heap.begin(), heap.end(), later);
  };
  const auto cross = [&](const Crossing& c) {
    if (!on_line[static_cast<std::size_t>(c.below)] || !on_line[static_cast<std::size_t>(c.above)]) return;
    const It ia = where[static_cast<std::size_t>(c.below)];
    const It ib = where[static_cast<std::size_t>(c.above)];
    if (std::next(ia) != ib) return;  // found again after the two traded places
    report(c.below, c.above);
    // The keys trade places in the nodes: the order stays right, as only these two cross here.
    std::swap(const_cast<Entry&>(*ia), const_cast<Entry&>(*ib));
    where[static_cast<std::size_t>(c.above)] = ia;
    where[static_cast<std::size_t>(c.below)] = ib;
    if (ia != line.begin()) watch(std::prev(ia), ia);
    if (std::next(ib) != line.end()) watch(ib, std::next(ib));
  };
  const auto insert = [&](int e) {
    ctx.fresh = e;
    const Entry entry{e, pts[static_cast<std::size_t>(lo(e))], pts[static_cast<std::size_t>(hi(e))]};
    where[static_cast<std::size_t>(e)] = line.insert(entry).first;
    on_line[static_cast<std::size_t>(e)] = 1;
    ctx.fresh = -1;
  };

  const std::size_t keys = pts.size();
  const Buckets by_lo = bucket_by(m, keys, [&](std::size_t e) { return lo(static_cast<int>(e)); });
  const Buckets by_hi = bucket_by(m, keys, [&](std::size_t e) { return hi(static_cast<int>(e)); });
  std::vector<int> verticals;  // vertical edges reaching the current point (they lie on its x)
  std::vector<int> through;    // edges on the line through the current point
  std::vector<int> at;         // every edge through the current point
  std::array<std::vector<int>, 2> passing, ending;  // of A and of B: through p, and ending or starting there
  for (std::size_t pi = 0; pi < keys; ++pi) {
    if (by_lo.begin[pi] == by_lo.begin[pi + 1] && by_hi.begin[pi] == by_hi.begin[pi + 1]) continue;
    const int p = static_cast<int>(pi);
    const Point& P = pts[pi];
    if (!heap.empty()) {
      const typename K::Vertex vp = K::vertex(P);
      while (!heap.empty() && K::compare_vertices(heap.front().at, vp) == Sign::negative) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Crossing c = std::move(heap.back());
        heap.pop_back();
        cross(c);
      }
    }
    ctx.p = &P;
    std::erase_if(verticals, [&](int v) { return hi(v) < p; });
    const It first = line.lower_bound(Probe{&P});
    // Vertical edges starting here meet every edge that runs across them.
    for (int k = by_lo.begin[pi]; k < by_lo.begin[pi + 1]; ++k) {
      const int v = by_lo.order[static_cast<std::size_t>(k)];
      if (!vertical(v)) continue;
      const Point& top = pts[static_cast<std::size_t>(hi(v))];
      for (It it = first; it != line.end() && side(*it, top) != Sign::negative; ++it) {
        const int t_end = hi(it->edge);
        if (t_end != p && t_end != hi(v)) report(v, it->edge);  // not at an end of both
      }
      verticals.push_back(v);
    }
    // The edges through p: on the line, then starting, then vertical; every two meet at p.
    through.clear();
    It after = first;
    for (; after != line.end() && side(*after, P) == Sign::zero; ++after) through.push_back(after->edge);
    const It before = first == line.begin() ? line.end() : std::prev(first);
    at.assign(through.begin(), through.end());
    for (int k = by_lo.begin[pi]; k < by_lo.begin[pi + 1]; ++k) {
      const int e = by_lo.order[static_cast<std::size_t>(k)];
      if (!vertical(e)) at.push_back(e);
    }
    const std::size_t were_on_line = through.size();
    at.insert(at.end(), verticals.begin(), verticals.end());
    // Each of A's with each of B's, but two that both end here: they meet at this end
    // alone, or along a segment whose other end is an event where one passes (or they are
    // the same segment, which relates nothing). An edge of a polygon passes through p only
    // where no other edge of that polygon meets p, so the pairs are as many as the edges
    // (a point where thousands of parts of both polygons meet, a fan's apex, costs
    // thousands, not millions).
    for (auto& list : passing) list.clear();
    for (auto& list : ending) list.clear();
    for (const int e : at) (lo(e) == p || hi(e) == p ? ending : passing)[static_cast<std::size_t>(group(e))].push_back(e);
    for (const int a : passing[0]) {
      for (const int b : passing[1]) report(a, b);
      for (const int b : ending[1]) report(a, b);
    }
    for (const int a : ending[0]) {
      for (const int b : passing[1]) report(a, b);
    }
    // Off the line, then back in the order after p: those passing p, and those starting.
    for (const int e : through) {
      line.erase(where[static_cast<std::size_t>(e)]);
      on_line[static_cast<std::size_t>(e)] = 0;
    }
    std::size_t inserted = 0;
    for (std::size_t k = 0; k < at.size() - verticals.size(); ++k) {
      const int e = at[k];
      if (k < were_on_line && hi(e) == p) continue;  // ends here
      insert(e);
      ++inserted;
    }
    if (inserted == 0) {
      if (before != line.end() && after != line.end()) watch(before, after);
      continue;
    }
    const It low = line.lower_bound(Probe{&P});
    It high = low;
    std::advance(high, static_cast<std::ptrdiff_t>(inserted) - 1);
    if (low != line.begin()) watch(std::prev(low), low);
    if (std::next(high) != line.end()) watch(high, std::next(high));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace detail {

// When a pair search over both polygons tries boxes within a budget before the red-blue sweep
// (the preparation, and step 3 when the preparation's findings were dropped): with an exact
// kernel over double points and search `sweep`, from kRedBlueFrom edges, when the chains'
// boxes are estimated to make more than kTrialChainPairs pairs per edge
// (estimated_chain_pairs); the budget is kMergesPerEdge merges of chains per edge. Measured
// (bench/README.md, "Nested wavy rings"): the sweep costs about what 4 to 8 merges per edge do.
inline constexpr std::size_t kRedBlueFrom = 4096;
inline constexpr double kTrialChainPairs = 8;
inline constexpr double kMergesPerEdge = 8;

template <Kernel K>
bool tries_boxes_first(const std::vector<typename K::Point>& pts, std::span<const SweepItem> items, PairSearch search) {
  return search == PairSearch::sweep && items.size() >= kRedBlueFrom &&
         estimated_chain_pairs<K>(pts, items) > kTrialChainPairs * static_cast<double>(items.size());
}
inline std::int64_t merge_budget(std::size_t items) { return static_cast<std::int64_t>(kMergesPerEdge * static_cast<double>(items)); }

// The sweep's pairs related on up to `threads` threads, into one Found per part in their
// order: relate(found[part], i, j) for each pair (i, j).
template <Kernel K, class Found, class Relate>
  requires(std::is_same_v<typename K::Point, Point> && K::is_exact)
void relate_red_blue_pairs(const std::vector<Point>& pts, std::span<const SweepItem> items, unsigned threads,
                           std::vector<Found>& found, Relate&& relate) {
  const std::vector<std::pair<int, int>> meeting = red_blue_meeting_pairs<K>(pts, items);
  const unsigned t = threads_for(meeting.size(), threads);
  found.assign(t, Found{});
  run_tasks(t, t, [&](std::size_t part) {
    const std::size_t from = meeting.size() * part / t, to = meeting.size() * (part + 1) / t;
    for (std::size_t k = from; k < to; ++k) relate(found[part], meeting[k].first, meeting[k].second);
  });
}

}  // namespace detail

}  // namespace mk
