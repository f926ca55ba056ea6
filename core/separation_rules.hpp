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
//      neighbour more than T from u. It is tested against u's line (nearer than the
//      segment), from the neighbour's distance d from w along s: the line is at least
//      d |du x ds| / (|du|_1 |ds|_inf) away. At a crossing, u is the crossing's other edge;
//      at an input point, the ring's edge before or after (only points on exactly two
//      edges, of one ring, are taken; any other input point refuses). Where the ring goes
//      straight on through an input point, the two edges are one line and N covers them.
//  (I) s and u disjoint: the distance of two disjoint segments is reached at an end of one
//      of them (in any norm), so every input point more than T from every input edge it
//      does not end. This involves the input alone and is decided when the output is
//      written (rounding_rules_keep_topology in rounding_boxes.hpp), by a grid over the
//      input points with boxes of half-size T/2 that each input edge walks row by row
//      (points_clear_of_edges in box_certificate.hpp).
// N and C are tested in step 3's fragment loop (step3_intersections.hpp), where each edge's
// vertices are at hand in order, sorted a moment before: per fragment one gap between two
// boxes, one slope (the far end's) and two comparisons, on data in cache. Each bound is
// proved with margins for its own rounding. Refusing is always safe: any input point inside
// an edge, on more than two edges, or on a ring of two points, any crossing whose edges are
// not found, or any test not proved, and the box certificate decides instead. N is implied
// by C (w lies on u, so a neighbour within T of w is within T of u's line); it is kept as
// the first, cheapest test.
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

// A lower bound on the gap between boxes p and q ({x0, y0, x1, y1}) along x or y: the
// largest of the four, computed and then taken one double down (no more than the exact gap;
// negative when the boxes meet).
inline double box_gap(const std::array<double, 4>& p, const std::array<double, 4>& q) {
  return next_down(std::max({q[0] - p[2], p[0] - q[2], q[1] - p[3], p[1] - q[3]}));
}

// How far points of a segment s through a vertex w get from another line u through w: a
// point of s at distance d from w (max norm) is at distance at least d |du x ds| /
// (|du|_1 |ds|_inf) from u's line (the max-norm distance to a line is |du x (p - w)| /
// |du|_1). `lo` bounds the factor's numerator from below and `hi` its denominator from
// above, each proved: the cross product of the rounded differences is within 4.01 eps
// (|p1| + |p2|) of the exact one (two differences, two products, one subtraction) and 8 eps
// is subtracted; the norms are rounded up by the factor 1 + 8 eps. Products too small for
// these relative bounds (under 2^-900) give no bound (lo 0).
struct Slope {
  double lo = 0, hi = 1;
};
inline Slope slope_between(const Point& u0, const Point& u1, double dsx, double dsy, double ds_inf_hi) {
  const double dux = u1.x - u0.x, duy = u1.y - u0.y;
  const double p1 = dux * dsy, p2 = duy * dsx;
  const double size = std::abs(p1) + std::abs(p2);
  if (!(size >= 0x1p-900)) return {};
  const double lo = next_down(std::abs(p1 - p2) - size * 0x1p-50);
  return {lo, (std::abs(dux) + std::abs(duy)) * (1 + 0x1p-50) * ds_inf_hi};
}

// Whether a point of s at distance at least `gap` from w (max norm) is more than t from u's
// line, given the slope between s and u: gap lo / hi > t, each side's rounding covered by a
// factor 1 -+ 8 eps. Subnormal and NaN values fail.
inline bool far_from_line(const Slope& slope, double gap, double t) {
  const double rhs = t * slope.hi * (1 + 0x1p-50);
  return rhs >= 0x1p-900 && slope.lo * gap * (1 - 0x1p-50) > rhs;
}

// Whether q lies strictly between p and r on one line (decided exactly).
template <Kernel K>
bool straight_corner(const Point& p, const Point& q, const Point& r) {
  if (K::orient2d(K::point(p), K::point(q), K::point(r)) != Sign::zero) return false;
  const auto between = [](double a, double b, double c) { return (a < b && b < c) || (a > b && b > c); };
  return between(p.x, q.x, r.x) || (p.x == q.x && q.x == r.x && between(p.y, q.y, r.y));
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
  SeparationRules() = default;  // inactive
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
      // Rule C at vertex w of this edge: the slope between this edge and the other edge
      // through w (the ring's edge `ring_edge` at an input point, else the crossing's other
      // segment); lo 0 (no bound) when the crossing's segments are not found.
      const double dsx = s1.x - s0.x, dsy = s1.y - s0.y;
      const double ds_inf_hi = std::max(std::abs(dsx), std::abs(dsy)) * (1 + 0x1p-50);
      const auto slope_at = [&](int w, const Edge& ring_edge) {
        if (w < np) {
          const Point& u0 = point(ring_edge.src);
          const Point& u1 = point(ring_edge.dst);
          // A straight corner (the ring goes on along the same line): the neighbour lies on
          // that line beyond w, as far from the ring's other edge as from w (rule N).
          if (detail::straight_corner<K>(w == edge.src ? u0 : u1, point(w), w == edge.src ? s1 : s0)) {
            return detail::Slope{HUGE_VAL, 1};
          }
          return detail::slope_between(u0, u1, dsx, dsy, ds_inf_hi);
        }
        const auto& v = arr.crossings[static_cast<std::size_t>(w - np)];
        if (detail::same_segment(s0, s1, v.a0, v.a1)) return detail::slope_between(v.b0, v.b1, dsx, dsy, ds_inf_hi);
        if (detail::same_segment(s0, s1, v.b0, v.b1)) return detail::slope_between(v.a0, v.a1, dsx, dsy, ds_inf_hi);
        return detail::Slope{};
      };
      int from = edge.src;
      std::array<double, 4> from_box = box(from);
      detail::Slope from_slope = slope_at(from, before);
      for (std::size_t k = 0; k <= inside.size(); ++k) {
        const bool last = k == inside.size();
        const int to = last ? edge.dst : inside[k];
        if (!last && to < np) return false;  // an input point inside the edge
        const std::array<double, 4> to_box = box(to);
        const detail::Slope to_slope = slope_at(to, after);
        const double gap = detail::box_gap(from_box, to_box);  // at most the exact points' distance
        if (!(gap > t_)) return false;  // N
        if (!detail::far_from_line(from_slope, gap, t_) || !detail::far_from_line(to_slope, gap, t_)) return false;  // C
        from = to;
        from_box = to_box;
        from_slope = to_slope;
      }
      return true;
    }
  }

 private:
  double r_ = 0, t_ = 0;
  std::vector<std::uint8_t> degree_;  // per input point
};

// Rules N and C over an arrangement whose fragments step 3 has made, in a pass of their own
// (each edge's inner vertices read back from its fragments): what step 3 decides as it makes
// them, decided again, for checking step 3's verdict (a trace hook sees the fragments). It
// costs about twice step 3's share (15 against 6-8 ms on star 1e4: the vertices come from
// memory, not from the cache the sort left them in), so bench_output measures the rules by
// Options::rounding_rules instead. True when the rules are active and hold on both polygons.
template <Kernel K>
bool separation_rules_hold(const Arrangement<K>& arr, unsigned threads = 1) {
  const SeparationRules<K> rules(arr, threads);
  if (!rules.active()) return false;
  std::array<bool, 2> holds{true, true};
  run_tasks(threads_for(arr.polygon[0].fragments.size() + arr.polygon[1].fragments.size(), threads), 2,
            [&](std::size_t g) {
              const PreparedPolygon& poly = arr.polygon[g];
              std::vector<int> inside;
              for (std::size_t c = 0; c + 1 < poly.cycle_first_fragment.size() && holds[g]; ++c) {
                const int first = poly.cycle_first_edge[c], end = poly.cycle_first_edge[c + 1];
                for (int f = poly.cycle_first_fragment[c], last = poly.cycle_first_fragment[c + 1]; f < last;) {
                  const int e = poly.fragments[static_cast<std::size_t>(f)].edge;
                  inside.clear();
                  for (; f + 1 < last && poly.fragments[static_cast<std::size_t>(f + 1)].edge == e; ++f) {
                    inside.push_back(poly.fragments[static_cast<std::size_t>(f)].to);
                  }
                  ++f;
                  if (!rules.edge_holds(arr, static_cast<int>(g), e, first, end, inside)) {
                    holds[g] = false;
                    break;
                  }
                }
              }
            });
  return holds[0] && holds[1];
}

}  // namespace mk
