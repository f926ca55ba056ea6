// Angular order of edge directions around a vertex, and sectors between two directions.
// [MK89 §4.3, Table 5] (the angle rules at a vertex, generalised to any degree)
// Preconditions: each direction joins two distinct input points; all directions compared
// emanate from one common vertex (which may itself be a crossing: only the directions
// matter, so the vertex is never evaluated).
#pragma once

#include <vector>

#include "kernel/kernel.hpp"

namespace mk {

// The direction of the vector points[to] - points[from].
struct Direction {
  int from = -1;
  int to = -1;
  Direction reversed() const { return {to, from}; }
  // The same pair of points (not merely the same direction).
  friend bool operator==(const Direction&, const Direction&) = default;
};

// The sector test, written once for every kind of direction: whether d lies strictly inside
// the counterclockwise sweep from `first` to `last`; when first and last point the same way
// the sweep is the full turn less that direction. Decided from cross(u, v), the Sign of the
// cross product u x v (positive when v lies less than half a turn counterclockwise of u),
// and, for parallel u and v only, same_way(u, v).
template <class D, class Cross, class SameWay>
bool is_in_ccw_sweep(const D& first, const D& last, const D& d, Cross&& cross, SameWay&& same_way) {
  const Sign fl = cross(first, last);
  if (fl == Sign::positive) return cross(first, d) == Sign::positive && cross(d, last) == Sign::positive;
  if (fl == Sign::negative) {
    // More than half a turn: everything but the closed sweep from last to first.
    return !(cross(last, d) != Sign::negative && cross(d, first) != Sign::negative);
  }
  const Sign fd = cross(first, d);
  if (same_way(first, last)) return fd != Sign::zero || !same_way(first, d);
  return fd == Sign::positive;  // half a turn
}

template <Kernel K>
class DirectionOrder {
 public:
  explicit DirectionOrder(const std::vector<typename K::Point>& points) : points_(points) {}

  // Angles in [0, pi) form the upper half, [pi, 2 pi) the lower one; east is angle 0.
  bool is_upper(Direction d) const {
    const Sign dy = K::compare_y(points_[d.to], points_[d.from]);
    return dy == Sign::positive || (dy == Sign::zero && K::compare_x(points_[d.to], points_[d.from]) == Sign::positive);
  }

  // Compares the angles of a and b in [0, 2 pi).
  Sign compare(Direction a, Direction b) const {
    // The same pair of points: no predicate needed (the common case of a fragment's own ray,
    // where proving a zero determinant would take the slowest exact stage).
    if (a.from == b.from && a.to == b.to) return Sign::zero;
    const bool ua = is_upper(a);
    const bool ub = is_upper(b);
    if (ua != ub) return ua ? Sign::negative : Sign::positive;
    return -K::orient_vectors(points_[a.from], points_[a.to], points_[b.from], points_[b.to]);
  }

  // Whether d lies strictly inside the counterclockwise sweep from `first` to `last`
  // (is_in_ccw_sweep below). A pair of points compared with itself or its reverse is
  // parallel without a predicate: proving a zero determinant takes the slowest exact stage.
  bool is_in_ccw_sector(Direction first, Direction last, Direction d) const {
    const auto cross = [&](Direction a, Direction b) {
      if (a == b || a == b.reversed()) return Sign::zero;
      return K::orient_vectors(points_[a.from], points_[a.to], points_[b.from], points_[b.to]);
    };
    const auto same_way = [&](Direction a, Direction b) { return a == b || is_upper(a) == is_upper(b); };
    return is_in_ccw_sweep(first, last, d, cross, same_way);
  }

  // Signed turn from direction a to direction b, counted in whole crossings of angle 0:
  // +1 when the counterclockwise turn (less than pi) wraps past east, -1 for a clockwise
  // turn that does, 0 otherwise. Summed over a closed cycle this is its turning number.
  int wraps(Direction a, Direction b) const {
    const Sign turn = K::orient_vectors(points_[a.from], points_[a.to], points_[b.from], points_[b.to]);
    if (turn == Sign::positive) return compare(b, a) == Sign::negative ? 1 : 0;
    if (turn == Sign::negative) return compare(a, b) == Sign::negative ? -1 : 0;
    return 0;
  }

 private:
  const std::vector<typename K::Point>& points_;
};

}  // namespace mk
