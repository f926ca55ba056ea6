// The nodes of OGC validity: at each point where a ring passes twice or rings meet (at a
// shared vertex, or a vertex inside another ring's edge), no ring may touch itself, no two
// rings may cross (their edges around the point must not interleave), and the rings of one
// polygon must not close a cycle of touches (which disconnects its interior).
// [OGC06-103 §6.1.11] (interior connected; rings touch at points) [MK89 §2.2]
// Preconditions: called by check_ogc_validity after its sweep found no crossing or
// overlapping edges; `touches` lists every (point, segment) where the point lies inside the
// segment. V is an exact kernel.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/sweep_status.hpp"

namespace mk {

enum class OgcDefect : unsigned char {
  none,
  invalid_coordinate,      // not finite
  too_few_points,          // a ring of fewer than 3 distinct points
  self_intersection,       // edges cross or overlap, or two rings cross at a point
  ring_self_intersection,  // a ring touches itself
  hole_outside_shell,
  nested_holes,
  nested_shells,           // a part's interior overlaps another part's
  disconnected_interior,   // rings of one polygon touch twice, or touch in a cycle
};

constexpr const char* ogc_defect_name(OgcDefect d) {
  switch (d) {
    case OgcDefect::none: return "valid";
    case OgcDefect::invalid_coordinate: return "invalid coordinate";
    case OgcDefect::too_few_points: return "too few points";
    case OgcDefect::self_intersection: return "self-intersection";
    case OgcDefect::ring_self_intersection: return "ring self-intersection";
    case OgcDefect::hole_outside_shell: return "hole outside shell";
    case OgcDefect::nested_holes: return "nested holes";
    case OgcDefect::nested_shells: return "nested shells";
    case OgcDefect::disconnected_interior: return "interior is disconnected";
  }
  return "?";
}


struct NodeVerdict {
  OgcDefect defect{};
  int ring = -1;
};

namespace detail {

// Union-find over rings and (point, polygon) nodes.
class TouchForest {
 public:
  explicit TouchForest(std::size_t n) : up_(n) { std::iota(up_.begin(), up_.end(), 0); }
  int add() {
    up_.push_back(static_cast<int>(up_.size()));
    return up_.back();
  }
  int find(int x) {
    while (up_[static_cast<std::size_t>(x)] != x) {
      up_[static_cast<std::size_t>(x)] = up_[static_cast<std::size_t>(up_[static_cast<std::size_t>(x)])];
      x = up_[static_cast<std::size_t>(x)];
    }
    return x;
  }
  // False when a and b were connected already (the new link closes a cycle).
  bool link(int a, int b) {
    const int ra = find(a), rb = find(b);
    if (ra == rb) return false;
    up_[static_cast<std::size_t>(ra)] = rb;
    return true;
  }

 private:
  std::vector<int> up_;
};

}  // namespace detail

template <Kernel V>
NodeVerdict check_validity_nodes(const std::vector<typename V::Point>& pts, const std::vector<std::vector<int>>& rings,
                                 const std::vector<SweepSegment>& seg, const std::vector<int>& seg_ring,
                                 const std::vector<std::pair<int, int>>& touches, const std::vector<int>& part) {
  // One incidence: ring `ring` passes through the point towards `a` and `b`.
  struct Incidence {
    int ring, a, b;
  };
  const std::size_t np = pts.size();
  std::vector<int> count(np + 1, 0);
  for (const auto& ring : rings) {
    for (const int p : ring) ++count[static_cast<std::size_t>(p) + 1];
  }
  for (const auto& t : touches) ++count[static_cast<std::size_t>(t.first) + 1];
  std::partial_sum(count.begin(), count.end(), count.begin());
  std::vector<Incidence> at(static_cast<std::size_t>(count[np]));
  {
    std::vector<int> fill(count.begin(), count.end() - 1);
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const auto& ring = rings[r];
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        at[static_cast<std::size_t>(fill[static_cast<std::size_t>(ring[i])]++)] = {static_cast<int>(r), ring[(i + n - 1) % n],
                                                                                  ring[(i + 1) % n]};
      }
    }
    for (const auto& [p, s] : touches) {
      at[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] = {seg_ring[static_cast<std::size_t>(s)],
                                                                          seg[static_cast<std::size_t>(s)].lo,
                                                                          seg[static_cast<std::size_t>(s)].hi};
    }
  }
  detail::TouchForest forest(rings.size());
  struct HalfEdge {
    int to;
    int label;  // the incidence it belongs to
  };
  std::vector<HalfEdge> around;
  std::vector<int> stack;
  std::vector<std::pair<int, int>> by_part;  // (polygon, ring) of the rings at one point
  for (std::size_t p = 0; p < np; ++p) {
    const int b = count[p], e = count[p + 1];
    if (e - b < 2) continue;
    // A ring passing twice touches itself.
    for (int i = b; i < e; ++i) {
      for (int j = i + 1; j < e; ++j) {
        if (at[static_cast<std::size_t>(i)].ring == at[static_cast<std::size_t>(j)].ring) {
          return {OgcDefect::ring_self_intersection, at[static_cast<std::size_t>(i)].ring};
        }
      }
      if (e - b > 8) break;  // many rings: the sort below finds repeats as neighbours
    }
    const auto& c = pts[p];
    around.clear();
    for (int i = b; i < e; ++i) {
      around.push_back({at[static_cast<std::size_t>(i)].a, i});
      around.push_back({at[static_cast<std::size_t>(i)].b, i});
    }
    if (e - b > 8) {
      std::vector<int> ring_ids;
      for (int i = b; i < e; ++i) ring_ids.push_back(at[static_cast<std::size_t>(i)].ring);
      std::sort(ring_ids.begin(), ring_ids.end());
      const auto dup = std::adjacent_find(ring_ids.begin(), ring_ids.end());
      if (dup != ring_ids.end()) return {OgcDefect::ring_self_intersection, *dup};
    }
    // Counterclockwise from east: the upper half-plane (and east itself) first.
    const auto upper = [&](int q) {
      const Sign dy = V::compare_y(pts[static_cast<std::size_t>(q)], c);
      return dy == Sign::positive || (dy == Sign::zero && V::compare_x(pts[static_cast<std::size_t>(q)], c) == Sign::positive);
    };
    bool same_direction = false;
    std::sort(around.begin(), around.end(), [&](const HalfEdge& x, const HalfEdge& y) {
      const bool ux = upper(x.to), uy = upper(y.to);
      if (ux != uy) return ux;
      const Sign o = V::orient2d(c, pts[static_cast<std::size_t>(x.to)], pts[static_cast<std::size_t>(y.to)]);
      if (o == Sign::zero && x.label != y.label) same_direction = true;
      return o == Sign::positive;
    });
    if (same_direction) return {OgcDefect::self_intersection, at[static_cast<std::size_t>(b)].ring};
    // Edges of two rings interleave around the point exactly when the rings cross there:
    // around the circle each ring's pair of edges must nest like parentheses.
    stack.clear();
    for (const HalfEdge& h : around) {
      if (!stack.empty() && stack.back() == h.label) {
        stack.pop_back();
      } else {
        stack.push_back(h.label);
      }
    }
    if (!stack.empty()) return {OgcDefect::self_intersection, at[static_cast<std::size_t>(b)].ring};
    // Touches within one polygon: a cycle through rings and touch points splits its interior.
    by_part.clear();
    for (int i = b; i < e; ++i) {
      const int r = at[static_cast<std::size_t>(i)].ring;
      by_part.push_back({part[static_cast<std::size_t>(r)], r});
    }
    std::sort(by_part.begin(), by_part.end());
    int node = -1;
    for (std::size_t k = 0; k < by_part.size(); ++k) {
      if (k == 0 || by_part[k].first != by_part[k - 1].first) node = forest.add();
      if (!forest.link(node, by_part[k].second)) return {OgcDefect::disconnected_interior, by_part[k].second};
    }
  }
  return {};
}

}  // namespace mk
