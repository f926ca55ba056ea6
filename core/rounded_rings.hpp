// The validity check of rounded rings used before OGC validity (core/ogc_validity.hpp): no
// ring collapses, no two edges cross, overlap or touch. Kept for the experiment harness's
// verdicts on rounded kernels, which compare outputs ring by ring.
// [MK89 §3.3] (detecting non-orientable rounded output)
// Preconditions: V is an exact kernel over doubles (its Point constructible from mk::Point).
#pragma once

#include <algorithm>
#include <optional>
#include <type_traits>
#include <vector>

#include "core/boolean_op.hpp"
#include "core/pairs.hpp"
#include "predicates/segments.hpp"

namespace mk {

namespace detail {

// Whether rings given as indices into `pts` (distinct points of doubles, in lexicographic
// order) form a valid output: no ring collapses (a repeated consecutive point), no two
// edges cross or overlap, and no vertex lies inside another edge. Decided exactly by V.
template <Kernel V>
bool are_valid_indexed_rings(const std::vector<Point>& pts_in, const std::vector<std::vector<int>>& rings) {
  std::vector<std::pair<int, int>> edges;
  for (const auto& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (r.size() > 1 && r[i] == r[(i + 1) % r.size()]) return false;
      if (r.size() > 1 && !(r.size() == 2 && i == 1)) edges.push_back({r[i], r[(i + 1) % r.size()]});
    }
  }
  std::vector<typename V::Point> pts;
  pts.reserve(pts_in.size());
  for (const Point& p : pts_in) pts.push_back(V::point(p));
  std::vector<int> x_rank(pts.size(), 0);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    x_rank[i] = x_rank[i - 1] + (V::compare_x(pts[i - 1], pts[i]) != Sign::zero);
  }
  std::vector<SweepItem> items;
  items.reserve(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto [s, e] = edges[k];
    items.push_back(sweep_item(s, e, 0, k > 0 && edges[k - 1].second == s));
  }
  bool valid = true;
  for_each_candidate_pair<V>(pts, x_rank, items, false, PairSearch::sweep, [&](int i, int j) {
    if (!valid) return;
    const SweepItem& a = items[i];
    const SweepItem& b = items[j];
    if (a.lo == b.lo && a.hi == b.hi) {
      valid = false;  // the same segment twice
      return;
    }
    const auto rel = relate_segments<V>(pts[a.lo], pts[a.hi], pts[b.lo], pts[b.hi]);
    if (rel.proper_crossing || rel.touches()) valid = false;
  });
  return valid;
}

inline bool lexicographically_less(const Point& a, const Point& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }

}  // namespace detail

// Whether rings of doubles form a valid output (detail::are_valid_indexed_rings), decided
// exactly by kernel V.
template <Kernel V>
bool is_valid_rounded_output(const std::vector<std::vector<Point>>& rings) {
  std::vector<Point> raw;
  for (const auto& r : rings) raw.insert(raw.end(), r.begin(), r.end());
  std::vector<std::size_t> order(raw.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return detail::lexicographically_less(raw[a], raw[b]); });
  std::vector<Point> pts;
  std::vector<int> id(raw.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || !(raw[order[k]] == raw[order[k - 1]])) pts.push_back(raw[order[k]]);
    id[order[k]] = static_cast<int>(pts.size()) - 1;
  }
  std::vector<std::vector<int>> indexed;
  std::size_t at = 0;
  for (const auto& r : rings) {
    indexed.emplace_back(id.begin() + static_cast<std::ptrdiff_t>(at), id.begin() + static_cast<std::ptrdiff_t>(at + r.size()));
    at += r.size();
  }
  return detail::are_valid_indexed_rings<V>(pts, indexed);
}

namespace detail {

// The check of are_valid_indexed_rings restricted to what rounding can change, for a
// result with few crossing points: only crossings move when rounded (input points are
// doubles), so an edge between two input points is the exact result's own, and the exact
// result passes the check (its cycles are vertex-complete, edges meet at shared vertices
// only). Every edge at a crossing is tested against every edge whose box meets its box, the
// same pairs the sweep would test; empty when there are more than `max_moved` such edges.
template <Kernel K, Kernel V>
std::optional<bool> are_valid_where_rounded(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded,
                                            std::size_t max_moved) {
  struct RoundedEdge {
    Point a, b;
    bool moved;
  };
  const int num_points = r.arrangement.num_points();
  std::vector<RoundedEdge> edges;
  std::vector<std::size_t> moved;
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    const auto& ids = r.cycles[c].vertices;
    const std::size_t n = ids.size();
    if (n < 2) continue;
    for (std::size_t i = 0; i < (n == 2 ? 1 : n); ++i) {
      const std::size_t j = (i + 1) % n;
      bool m = ids[i] >= num_points || ids[j] >= num_points;
      if constexpr (!std::is_same_v<typename K::Point, Point>) {
        // Input points that are not doubles (exact rational input) may move too.
        const auto stays = [&](std::size_t k) {
          return K::compare_vertices(K::vertex(K::point(rounded[c][k])), r.vertex(ids[k])) == Sign::zero;
        };
        m = m || !stays(i) || !stays(j);
      }
      if (m) {
        if (moved.size() == max_moved) return std::nullopt;
        moved.push_back(edges.size());
      }
      edges.push_back({rounded[c][i], rounded[c][j], m});
    }
  }
  if (moved.empty()) return true;
  struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  };
  const auto box = [](const RoundedEdge& e) {
    return Box{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y)};
  };
  Box all = box(edges[moved[0]]);
  std::vector<Box> moved_box;
  for (const std::size_t m : moved) {
    const RoundedEdge& e = edges[m];
    if (e.a == e.b) return false;  // a collapsed edge
    const Box b = box(e);
    moved_box.push_back(b);
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
  }
  for (std::size_t f = 0; f < edges.size(); ++f) {
    const Box fb = box(edges[f]);
    if (!fb.meets(all)) continue;
    for (std::size_t k = 0; k < moved.size(); ++k) {
      const std::size_t e = moved[k];
      // Each pair once: a moved edge meets the moved edges after it only.
      if (e == f || (edges[f].moved && f < e) || !fb.meets(moved_box[k])) continue;
      const RoundedEdge& p = edges[e];
      const RoundedEdge& q = edges[f];
      if ((p.a == q.a && p.b == q.b) || (p.a == q.b && p.b == q.a)) return false;  // the same segment twice
      const auto rel = relate_segments<V>(V::point(p.a), V::point(p.b), V::point(q.a), V::point(q.b));
      if (rel.proper_crossing || rel.touches()) return false;
    }
  }
  return true;
}

}  // namespace detail

// The same check on a result's cycles, given their vertices rounded: the input points keep
// their lexicographic ids (prepare numbers them so), so only the crossings need sorting,
// and a merge puts every rounded point in order. Linear in the input points used, plus
// k log k for the k crossings.
template <Kernel K, Kernel V>
bool is_valid_rounded_result(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded) {
  // Few crossings: test the edges at them only, in one pass over the edges.
  if (const auto local = detail::are_valid_where_rounded<K, V>(r, rounded, 64)) return *local;
  const int num_points = r.arrangement.num_points();
  std::vector<int> slot(static_cast<std::size_t>(r.arrangement.num_vertices()), -1);
  std::vector<std::pair<int, Point>> collected, crossings;  // (id, rounded point)
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    for (std::size_t k = 0; k < r.cycles[c].vertices.size(); ++k) {
      const int id = r.cycles[c].vertices[k];
      if (slot[id] >= 0) continue;
      if (id < num_points) {
        slot[id] = static_cast<int>(collected.size());
        collected.push_back({id, rounded[c][k]});
      } else {
        slot[id] = 0;
        crossings.push_back({id, rounded[c][k]});
      }
    }
  }
  // The input points in id order, by one scan of the ids (no sort).
  std::vector<std::pair<int, Point>> inputs;
  inputs.reserve(collected.size());
  for (int id = 0; id < num_points; ++id) {
    if (slot[id] >= 0) inputs.push_back(collected[static_cast<std::size_t>(slot[id])]);
  }
  collected = {};
  // Input points of doubles round to themselves; exact rational inputs may not, and then
  // they are sorted like the crossings.
  for (std::size_t k = 1; k < inputs.size(); ++k) {
    if (detail::lexicographically_less(inputs[k].second, inputs[k - 1].second)) {
      crossings.insert(crossings.end(), inputs.begin(), inputs.end());
      inputs.clear();
      break;
    }
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const auto& a, const auto& b) { return detail::lexicographically_less(a.second, b.second); });
  std::vector<Point> pts;
  pts.reserve(inputs.size() + crossings.size());
  std::size_t i = 0, j = 0;
  while (i < inputs.size() || j < crossings.size()) {
    const bool take_input = j == crossings.size() ||
                            (i < inputs.size() && !detail::lexicographically_less(crossings[j].second, inputs[i].second));
    const auto& [id, p] = take_input ? inputs[i++] : crossings[j++];
    if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
    slot[id] = static_cast<int>(pts.size()) - 1;
  }
  std::vector<std::vector<int>> indexed(r.cycles.size());
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    indexed[c].reserve(r.cycles[c].vertices.size());
    for (const int id : r.cycles[c].vertices) indexed[c].push_back(slot[id]);
  }
  return detail::are_valid_indexed_rings<V>(pts, indexed);
}

}  // namespace mk
