// Which hot pixels each segment meets, without walking along it: a sweep in x answers "which
// segments cross this vertical pixel side" by binary search in the status (segments ordered
// by height), a sweep in y the horizontal sides, and a segment's own end points give the
// rest; axis-parallel segments are looked up directly. O((n + h + m) log n) for n segments,
// h hot pixels and m incidences, however many pixels a segment spans.
// [Ho99] (hot pixels) [BHO07] (intersection-sensitive snap rounding) [Sh76] (sweep status)
// Preconditions: the segments do not cross each other (they may touch and overlap); G is a
// snap geometry (arithmetic/snap_grid.hpp: SnapGeometry): static compare_x, compare_y,
// orient2d on G::Point, and pixel_of, centre, corner, compare_along on a grid. Pixels are
// half-open, so that every point lies in exactly one.
#pragma once

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "core/sweep_status.hpp"

namespace mk {

// Whether segment ab (a in pixel pa, b in pixel pb) meets pixel p = [x0, x1) x [y0, y1):
// at an end point, inside the open square, or on its closed-open left or bottom side (the
// parts of the boundary the pixel owns).
template <class G, class Px>
bool segment_meets_pixel(G& g, const typename G::Point& a, const typename G::Point& b, const Px& pa, const Px& pb,
                         const Px& p) {
  if (pa == p || pb == p) return true;
  // Pixel indices are monotone in the coordinates: the segment's pixels span the box of its
  // ends' pixels.
  if (p.x < std::min(pa.x, pb.x) || p.x > std::max(pa.x, pb.x) || p.y < std::min(pa.y, pb.y) || p.y > std::max(pa.y, pb.y)) {
    return false;
  }
  const auto c00 = g.corner(p, 0, 0), c10 = g.corner(p, 1, 0), c01 = g.corner(p, 0, 1), c11 = g.corner(p, 1, 1);
  const bool a_left = G::compare_x(a, b) != Sign::positive;
  const auto& xmin = a_left ? a : b;
  const auto& xmax = a_left ? b : a;
  const bool a_low = G::compare_y(a, b) != Sign::positive;
  const auto& ymin = a_low ? a : b;
  const auto& ymax = a_low ? b : a;
  // The open square: the segment's ranges overlap it and its line separates the corners.
  if (G::compare_x(xmax, c00) == Sign::positive && G::compare_x(xmin, c10) == Sign::negative &&
      G::compare_y(ymax, c00) == Sign::positive && G::compare_y(ymin, c01) == Sign::negative) {
    bool above = false, below = false;
    for (const auto* c : {&c00, &c10, &c01, &c11}) {
      const Sign s = G::orient2d(a, b, *c);
      above = above || s == Sign::positive;
      below = below || s == Sign::negative;
    }
    if (above && below) return true;
  }
  // The left side {x0} x [y0, y1).
  if (G::compare_x(xmin, c00) != Sign::positive && G::compare_x(xmax, c00) != Sign::negative) {
    if (G::compare_x(a, b) == Sign::zero) {
      if (G::compare_y(ymax, c00) != Sign::negative && G::compare_y(ymin, c01) == Sign::negative) return true;
    } else if (G::orient2d(xmin, xmax, c00) != Sign::positive && G::orient2d(xmin, xmax, c01) == Sign::positive) {
      return true;
    }
  }
  // The bottom side [x0, x1) x {y0}.
  if (G::compare_y(ymin, c00) != Sign::positive && G::compare_y(ymax, c00) != Sign::negative) {
    if (G::compare_y(a, b) == Sign::zero) {
      if (G::compare_x(xmax, c00) != Sign::negative && G::compare_x(xmin, c10) == Sign::negative) return true;
    } else if (G::orient2d(ymin, ymax, c00) != Sign::negative && G::orient2d(ymin, ymax, c10) == Sign::negative) {
      return true;
    }
  }
  return false;
}

namespace detail {

// A sweep's frame: the x-sweep reads points as they are; the y-sweep reads them mirrored in
// the diagonal (x and y swapped, which reverses orientations), so one sweep serves both.
template <class G, bool Mirrored>
struct SweepFrame {
  using Point = typename G::Point;
  static Sign compare_x(const Point& a, const Point& b) { return Mirrored ? G::compare_y(a, b) : G::compare_x(a, b); }
  static Sign compare_y(const Point& a, const Point& b) { return Mirrored ? G::compare_x(a, b) : G::compare_y(a, b); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return Mirrored ? -G::orient2d(a, b, c) : G::orient2d(a, b, c);
  }
  template <class Px>
  static auto primary(const Px& p) { return Mirrored ? p.y : p.x; }
  template <class Px>
  static auto secondary(const Px& p) { return Mirrored ? p.x : p.y; }
  template <class Px, class I>
  static Px pixel(I prim, I sec) { return Mirrored ? Px{sec, prim} : Px{prim, sec}; }
};

// One sweep in frame F: for every segment not parallel to F's y-axis, the hot pixels whose
// sides along that axis it meets (candidates, tested exactly by the caller); for the
// segments parallel to it, every hot pixel met, looked up directly.
template <class F, class G, class Px, class Emit>
void side_sweep(G& g, const std::vector<typename G::Point>& pts, const std::vector<Px>& pixel_of_point,
                const std::vector<std::pair<int, int>>& segments, const std::vector<Px>& hot, Emit&& emit) {
  using Point = typename G::Point;
  // Hot pixels in the frame's order (by primary, then secondary index).
  std::vector<int> by_frame(hot.size());
  std::iota(by_frame.begin(), by_frame.end(), 0);
  std::sort(by_frame.begin(), by_frame.end(), [&](int a, int b) {
    const Px& p = hot[static_cast<std::size_t>(a)];
    const Px& q = hot[static_cast<std::size_t>(b)];
    return std::pair(F::primary(p), F::secondary(p)) < std::pair(F::primary(q), F::secondary(q));
  });
  const auto hot_range = [&](auto prim, auto sec_lo, auto sec_hi) {  // [first, last) of by_frame
    const auto key = [&](int i) {
      const Px& p = hot[static_cast<std::size_t>(i)];
      return std::pair(F::primary(p), F::secondary(p));
    };
    const auto lo = std::lower_bound(by_frame.begin(), by_frame.end(), std::pair(prim, sec_lo),
                                     [&](int i, const auto& k) { return key(i) < k; });
    const auto hi = std::upper_bound(lo, by_frame.end(), std::pair(prim, sec_hi),
                                     [&](const auto& k, int i) { return k < key(i); });
    return std::pair(lo, hi);
  };

  // Points in the frame's lexicographic order; segments by those ranks.
  const std::size_t n = pts.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Sign s = F::compare_x(pts[static_cast<std::size_t>(a)], pts[static_cast<std::size_t>(b)]);
    return s == Sign::negative || (s == Sign::zero && F::compare_y(pts[static_cast<std::size_t>(a)], pts[static_cast<std::size_t>(b)]) == Sign::negative);
  });
  std::vector<int> rank(n);
  for (std::size_t k = 0; k < n; ++k) rank[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  std::vector<Point> ranked(n);
  for (std::size_t k = 0; k < n; ++k) ranked[k] = pts[static_cast<std::size_t>(order[k])];
  std::vector<SweepSegment> seg(segments.size());
  std::vector<std::vector<int>> starting(n), ending(n), incident(n);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto [u, w] = segments[i];
    const int ru = rank[static_cast<std::size_t>(u)], rw = rank[static_cast<std::size_t>(w)];
    seg[i] = {std::min(ru, rw), std::max(ru, rw)};
    const Px& pu = pixel_of_point[static_cast<std::size_t>(u)];
    const Px& pw = pixel_of_point[static_cast<std::size_t>(w)];
    if (F::compare_x(pts[static_cast<std::size_t>(u)], pts[static_cast<std::size_t>(w)]) == Sign::zero) {
      // Parallel to the frame's y-axis: one column of pixels, a range of rows.
      const auto [lo, hi] = hot_range(F::primary(pu), std::min(F::secondary(pu), F::secondary(pw)),
                                       std::max(F::secondary(pu), F::secondary(pw)));
      for (auto it = lo; it != hi; ++it) emit(static_cast<int>(i), *it);
      continue;
    }
    starting[static_cast<std::size_t>(seg[i].lo)].push_back(static_cast<int>(i));
    ending[static_cast<std::size_t>(seg[i].hi)].push_back(static_cast<int>(i));
    incident[static_cast<std::size_t>(seg[i].lo)].push_back(static_cast<int>(i));
    incident[static_cast<std::size_t>(seg[i].hi)].push_back(static_cast<int>(i));
  }

  // The lines carrying pixel sides: boundary k is the line at (k - 1/2) g in the frame's x.
  using Index = decltype(F::primary(hot.front()));
  std::vector<Index> lines;
  for (const Px& p : hot) {
    lines.push_back(F::primary(p));
    lines.push_back(F::primary(p) + 1);
  }
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());

  SweepStatus<F, true> status(ranked, seg);
  std::size_t next_point = 0;
  for (const Index k : lines) {
    const Point line_point = g.corner(F::template pixel<Px>(k, Index{0}), 0, 0);  // its x is the line's
    // Points left of the line: their segments leave and enter.
    const auto advance_to = [&](bool include_on_line) {
      while (next_point < n) {
        const Sign s = F::compare_x(ranked[next_point], line_point);
        if (s == Sign::positive || (s == Sign::zero && !include_on_line)) break;
        std::size_t end = next_point + 1;
        while (end < n && F::compare_x(ranked[end], ranked[next_point]) == Sign::zero) ++end;
        for (std::size_t r = next_point; r < end; ++r) {
          for (const int i : ending[r]) status.erase(i);
        }
        for (std::size_t r = next_point; r < end; ++r) {
          for (const int i : starting[r]) status.insert(i);
        }
        next_point = end;
      }
    };
    advance_to(false);
    // Segments ending on the line leave before the queries (they show as end points on it);
    // those starting on it enter after.
    std::size_t on_begin = next_point, on_end = next_point;
    while (on_end < n && F::compare_x(ranked[on_end], line_point) == Sign::zero) ++on_end;
    for (std::size_t r = on_begin; r < on_end; ++r) {
      for (const int i : ending[r]) status.erase(i);
    }
    // The sides on this line: the left sides of pixels in column k, the right sides of
    // pixels in column k - 1.
    for (const Index column : {k, k - 1}) {
      const auto [lo, hi] = hot_range(column, std::numeric_limits<Index>::min(), std::numeric_limits<Index>::max());
      for (auto it = lo; it != hi; ++it) {
        const Px& p = hot[static_cast<std::size_t>(*it)];
        const Point bottom = g.corner(F::template pixel<Px>(k, F::secondary(p)), 0, 0);
        const Point top = g.corner(F::template pixel<Px>(k, F::secondary(p) + 1), 0, 0);
        for (auto s = status.first_not_below(bottom); s != status.end() && status.side(s, top) != Sign::negative; ++s) {
          emit(s->segment, *it);
        }
        // Segments with an end on the line, between the side's ends.
        for (std::size_t r = on_begin; r < on_end; ++r) {
          if (F::compare_y(ranked[r], bottom) == Sign::negative || F::compare_y(ranked[r], top) == Sign::positive) continue;
          for (const int i : incident[r]) emit(i, *it);
        }
      }
    }
    for (std::size_t r = on_begin; r < on_end; ++r) {
      for (const int i : starting[r]) status.insert(i);
    }
    next_point = on_end;
  }
}

}  // namespace detail

// For every segment (a pair of point indices), the hot pixels it meets other than the pixels
// of its own end points, each once, in no particular order. `hot` holds distinct pixels.
template <class G, class Px>
std::vector<std::vector<int>> hot_pixels_met(G& g, const std::vector<typename G::Point>& pts,
                                             const std::vector<Px>& pixel_of_point,
                                             const std::vector<std::pair<int, int>>& segments, const std::vector<Px>& hot) {
  std::vector<std::vector<int>> met(segments.size());
  if (hot.empty()) return met;
  std::vector<std::pair<int, int>> candidates;
  const auto emit = [&](int s, int h) { candidates.push_back({s, h}); };
  detail::side_sweep<detail::SweepFrame<G, false>>(g, pts, pixel_of_point, segments, hot, emit);
  detail::side_sweep<detail::SweepFrame<G, true>>(g, pts, pixel_of_point, segments, hot, emit);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const auto& [s, h] : candidates) {
    const auto [u, w] = segments[static_cast<std::size_t>(s)];
    const Px& pu = pixel_of_point[static_cast<std::size_t>(u)];
    const Px& pw = pixel_of_point[static_cast<std::size_t>(w)];
    const Px& p = hot[static_cast<std::size_t>(h)];
    if (p == pu || p == pw) continue;
    if (segment_meets_pixel(g, pts[static_cast<std::size_t>(u)], pts[static_cast<std::size_t>(w)], pu, pw, p)) {
      met[static_cast<std::size_t>(s)].push_back(h);
    }
  }
  return met;
}

}  // namespace mk
