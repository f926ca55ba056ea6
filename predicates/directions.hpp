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
// the sweep is the full turn less that direction. `compare(u, v)` orders directions by
// angle, counterclockwise from any fixed reference direction (negative: u comes first;
// zero: the same direction), which makes the sweep an interval of that order or the
// complement of one.
// `first_last` is compare(first, last), for callers that test many d against one sweep.
template <class D, class Compare>
bool is_in_ccw_sweep(Sign first_last, const D& first, const D& last, const D& d, Compare&& compare) {
  const Sign fd = compare(first, d);
  if (first_last == Sign::zero) return fd != Sign::zero;
  if (first_last == Sign::negative && fd != Sign::negative) return false;
  if (first_last == Sign::positive && fd == Sign::negative) return true;
  return compare(d, last) == Sign::negative;
}
template <class D, class Compare>
bool is_in_ccw_sweep(const D& first, const D& last, const D& d, Compare&& compare) {
  return is_in_ccw_sweep(compare(first, last), first, last, d, compare);
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
    return compare_known(a, is_upper(a), b, is_upper(b));
  }
  // compare, given whether a and b lie in the upper half.
  Sign compare_known(Direction a, bool ua, Direction b, bool ub) const {
    if (a.from == b.from && a.to == b.to) return Sign::zero;
    if (ua != ub) return ua ? Sign::negative : Sign::positive;
    return -K::orient_vectors(points_[a.from], points_[a.to], points_[b.from], points_[b.to]);
  }

  // Whether d lies strictly inside the counterclockwise sweep from `first` to `last`
  // (is_in_ccw_sweep, in the order of `compare`).
  bool is_in_ccw_sector(Direction first, Direction last, Direction d) const {
    return is_in_ccw_sweep(first, last, d, [this](Direction u, Direction v) { return compare(u, v); });
  }

  // The sweep from `first` to `last` for testing many directions: the half-planes of its
  // ends and their order, found once. contains(d) == is_in_ccw_sector(first, last, d).
  class Sector {
   public:
    Sector(const DirectionOrder& order, Direction first, Direction last)
        : order_(&order), first_(first), last_(last), first_upper_(order.is_upper(first)),
          last_upper_(order.is_upper(last)),
          first_last_(order.compare_known(first, first_upper_, last, last_upper_)) {}
    bool contains(Direction d) const {
      const bool d_upper = order_->is_upper(d);
      const auto upper = [&](Direction u) { return u == first_ ? first_upper_ : (u == last_ ? last_upper_ : d_upper); };
      return is_in_ccw_sweep(first_last_, first_, last_, d,
                             [&](Direction u, Direction v) { return order_->compare_known(u, upper(u), v, upper(v)); });
    }

   private:
    const DirectionOrder* order_;
    Direction first_, last_;
    bool first_upper_, last_upper_;
    Sign first_last_;
  };

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
