// A certificate that rounding a valid exact result to its nearest doubles kept it valid,
// proved from the arrangement while step 3 builds it, instead of from a grid of the
// result's vertices afterwards. It proves the condition of the box certificate
// (box_certificate.hpp: no vertex's box meets the hull of an edge it does not end, and every
// edge's end boxes are apart) for every pair at once.
//
// Let R be at least every crossing's box extent (hi - lo, in x and in y). A result vertex's
// box is centred on its rounded point with half-sizes at most R and holds its exact point, so
// it lies within 2R (max norm) of the exact point, and an edge's hull within 2R of the exact
// segment. The condition therefore holds once every result vertex is more than T = 4R from
// every result edge it does not end, and every result edge's ends are more than T apart.
// Every result edge lies on an input edge between two arrangement vertices, and every result
// vertex is an arrangement vertex; for a vertex x on input edge s and a result edge e on
// input edge u, three rules cover every pair:
//  (N) s = u, or x on u: along each input edge, consecutive arrangement vertices more than T
//      apart along x or y. Both coordinates are monotone along a line, so every vertex
//      beyond the next one is at least as far (this also makes every result edge long).
//  (C) s and u meet at one point w, not collinear: the distance from s's points to segment u
//      is convex along s and zero at w, so it is smallest at w's neighbours on s: each
//      neighbour more than T from u (tested against u's line, which is nearer). At a crossing, u is the crossing's other edge; at an
//      input point, the ring's edge before or after (only points on exactly two edges, of
//      one ring, are taken; any other input point refuses).
//  (I) s and u disjoint: the distance of two disjoint segments is reached at an end of one
//      of them (in any norm), so every input point more than T from every input edge it
//      does not end. This involves the input alone and is decided when the output is
//      written (rounding_rules_keep_topology in rounding_boxes.hpp), by the box certificate's grid over the input
//      points with boxes of half-size T/2.
// N and C are tested in step 3's fragment loop (step3_intersections.hpp), where each edge's
// vertices are at hand in order, sorted a moment before: two or three tests per fragment
// on data in cache. Every test is proved with margins for its own rounding (the box
// certificate's tests, on boxes grown by T). Refusing is always safe: any input point
// inside an edge, on more than two edges, or on a ring of two points, any crossing whose
// edges are not found, or any test not proved, and the box certificate decides instead.
// [HP02] (vertices apart from edges they are not on) [GM98] [MK89 §3.1 step 3]
// Preconditions: the exact result is valid (to_output.hpp); the kernel's crossings keep
// their two segments and a box holding their exact point (CrossingSegments).
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/arrangement.hpp"
#include "core/parallel.hpp"
#include "core/box_certificate.hpp"

namespace mk {

// Up to this many crossings on its cycles, a result's rounding is certified exactly near them
// (rounding_motion.hpp); beyond, from the arrangement's rules or the boxes first.
inline constexpr std::size_t kFewCrossingsForExactCertificate = 256;

// A kernel whose crossings keep the two input segments they lie on (a0a1 and b0b1), besides
// a box holding their exact point, over input points of doubles.
template <class K>
concept CrossingSegments = VertexBoxes<K> && std::same_as<typename K::Point, Point> &&
                           requires(const typename K::Vertex& v) {
                             { v.a0 } -> std::convertible_to<Point>;
                             { v.a1 } -> std::convertible_to<Point>;
                             { v.b0 } -> std::convertible_to<Point>;
                             { v.b1 } -> std::convertible_to<Point>;
                           };

namespace detail {

// Whether boxes p and q ({x0, y0, x1, y1}) are more than t apart along x or y: the largest
// gap, computed and then taken one double down (no more than the exact gap), above t.
inline bool boxes_apart_by(const std::array<double, 4>& p, const std::array<double, 4>& q, double t) {
  return next_down(std::max({q[0] - p[2], p[0] - q[2], q[1] - p[3], p[1] - q[3]})) > t;
}

// Whether every point of box b lies more than t (max norm) from the line through u0 and u1,
// so from the segment: the box grown by t clear along the line's normal (the box
// certificate's test, the segment a hull of two points). Beyond the segment's ends the line
// is nearer than the segment, so this may refuse what the segment's distance would allow;
// never the other way. A box too wide for doubles is never cleared (NaN and infinity
// compare false).
inline bool box_far_from_line(const std::array<double, 4>& b, double t, const Point& u0, const Point& u1) {
  const Point c{b[0] + (b[2] - b[0]) / 2, b[1] + (b[3] - b[1]) / 2};
  const double hx = rounded_up(rounded_up(std::max(c.x - b[0], b[2] - c.x)) + t);
  const double hy = rounded_up(rounded_up(std::max(c.y - b[1], b[3] - c.y)) + t);
  return clear_along_normal({c, hx, hy}, {u0, 0, 0}, {u1, 0, 0});
}

inline bool same_segment(const Point& s0, const Point& s1, const Point& a, const Point& b) {
  return (s0 == a && s1 == b) || (s0 == b && s1 == a);
}

}  // namespace detail

// Rules N and C (see the top of this file) as step 3 makes each edge's fragments. Inactive
// (threshold 0) for kernels without CrossingSegments and for arrangements with few crossings
// or many more edges than crossings (there the box certificate's grid, which skips what did
// not move, costs less than a test per fragment).
template <Kernel K>
class SeparationRules {
 public:
  SeparationRules(const Arrangement<K>& arr, unsigned threads) {
    if constexpr (CrossingSegments<K>) {
      const std::size_t crossings = arr.crossings.size();
      const std::size_t edges = arr.polygon[0].edges.size() + arr.polygon[1].edges.size();
      if (crossings <= kFewCrossingsForExactCertificate || 4 * crossings < edges) return;
      // R: the largest extent of a crossing's box, found in parts on the threads.
      const unsigned t = threads_for(crossings, threads);
      const std::size_t parts = t > 1 ? 8 * static_cast<std::size_t>(t) : 1;
      std::vector<double> part_max(parts, 0.0);
      run_tasks(t, parts, [&](std::size_t part) {
        double m = 0;
        for (std::size_t i = crossings * part / parts, last = crossings * (part + 1) / parts; i < last; ++i) {
          const std::array<double, 4> b = K::vertex_box(arr.crossings[i]);
          m = std::max({m, detail::rounded_up(b[2] - b[0]), detail::rounded_up(b[3] - b[1])});
        }
        part_max[part] = m;
      });
      double r = 0;
      for (const double m : part_max) r = std::max(r, m);
      // T above 4R: the product's rounding is covered by the factor (1 + 2^-50).
      const double big_t = std::max(detail::rounded_up(4 * r * (1 + 0x1p-50)), DBL_MIN);
      if (!std::isfinite(big_t) || !(r < HUGE_VAL)) return;
      // How many edges of either polygon end at each input point (saturated at 3).
      degree_.assign(arr.points.size(), 0);
      for (const PreparedPolygon& poly : arr.polygon) {
        for (const Edge& e : poly.edges) {
          for (const int p : {e.src, e.dst}) {
            auto& d = degree_[static_cast<std::size_t>(p)];
            d = static_cast<std::uint8_t>(std::min(3, d + 1));
          }
        }
      }
      r_ = r;
      t_ = big_t;
    }
  }

  bool active() const { return t_ > 0; }
  double threshold() const { return t_; }
  double half_size_bound() const { return r_; }

  // Whether rules N and C hold along edge e of polygon g (its cycle's edges are [first,
  // end)), the vertices step 3 inserted inside it given in order along it.
  bool edge_holds(const Arrangement<K>& arr, int g, int e, int first, int end, std::span<const int> inside) const {
    if constexpr (!CrossingSegments<K>) {
      return false;
    } else {
      const PreparedPolygon& poly = arr.polygon[static_cast<std::size_t>(g)];
      if (end - first < 3) return false;
      const Edge& edge = poly.edges[static_cast<std::size_t>(e)];
      const Edge& before = poly.edges[static_cast<std::size_t>(e == first ? end - 1 : e - 1)];
      const Edge& after = poly.edges[static_cast<std::size_t>(e + 1 == end ? first : e + 1)];
      if (degree_[static_cast<std::size_t>(edge.src)] != 2 || degree_[static_cast<std::size_t>(edge.dst)] != 2 ||
          before.dst != edge.src || after.src != edge.dst) {
        return false;
      }
      const int np = arr.num_points();
      const auto point = [&](int id) -> const Point& { return arr.points[static_cast<std::size_t>(id)]; };
      const Point& s0 = point(edge.src);
      const Point& s1 = point(edge.dst);
      const auto box = [&](int id) {
        if (id < np) {
          const Point& p = point(id);
          return std::array<double, 4>{p.x, p.y, p.x, p.y};
        }
        return K::vertex_box(arr.crossings[static_cast<std::size_t>(id - np)]);
      };
      // Rule C at vertex w of this edge, for n (w's neighbour along it): n's box far from
      // the other edge through w.
      const auto far_from_other = [&](int w, const std::array<double, 4>& n, const Edge& ring_edge) {
        if (w < np) return detail::box_far_from_line(n, t_, point(ring_edge.src), point(ring_edge.dst));
        const auto& v = arr.crossings[static_cast<std::size_t>(w - np)];
        if (detail::same_segment(s0, s1, v.a0, v.a1)) return detail::box_far_from_line(n, t_, v.b0, v.b1);
        if (detail::same_segment(s0, s1, v.b0, v.b1)) return detail::box_far_from_line(n, t_, v.a0, v.a1);
        return false;
      };
      int from = edge.src;
      std::array<double, 4> from_box = box(from);
      for (std::size_t k = 0; k <= inside.size(); ++k) {
        const bool last = k == inside.size();
        const int to = last ? edge.dst : inside[k];
        if (!last && to < np) return false;  // an input point inside the edge
        const std::array<double, 4> to_box = box(to);
        if (!detail::boxes_apart_by(from_box, to_box, t_)) return false;  // N
        if (!far_from_other(from, to_box, before) || !far_from_other(to, from_box, after)) return false;  // C
        from = to;
        from_box = to_box;
      }
      return true;
    }
  }

 private:
  double r_ = 0, t_ = 0;
  std::vector<std::uint8_t> degree_;  // per input point
};

}  // namespace mk
