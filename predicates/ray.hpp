// Exact winding numbers at a point infinitesimally beside an edge, by a vertical ray from a
// symbolically perturbed point, from orientations of input points only.
// [MK89 §4.3] (locating one vertex per ring) [MK89 §3.2] (point location by a ray)
// Preconditions: v != t.
#pragma once

#include "kernel/kernel.hpp"
#include "predicates/segments.hpp"

namespace mk {

enum class Side : signed char { right = -1, left = 1 };

// Sign of orient(a, b, q) for the query point q of vertical_ray_crossing (below): which side
// of the line a -> b the point just `side` of v -> t near v lies on. Never zero: the first
// non-zero term of orient(a, b, v) + e (b - a) x (t - v) + s e^2 (b - a) x n.
// `v_is_end`: the caller knows that v is a or b (the first term is zero, and an exact
// predicate's filter cannot tell a zero cheaply).
template <Kernel K>
int orient_beside(const typename K::Point& a, const typename K::Point& b, const typename K::Point& v,
                  const typename K::Point& t, Side side, bool v_is_end = false) {
  int o = v_is_end ? 0 : static_cast<int>(K::orient2d(a, b, v));
  if (o == 0) o = static_cast<int>(K::orient_vectors(a, b, v, t));
  if (o == 0) {
    // b - a is parallel to t - v: cross(b - a, n) = dot(b - a, t - v), positive when they
    // point the same way.
    const bool same = compare_xy<K>(b, a) == compare_xy<K>(t, v);
    o = (side == Side::left ? 1 : -1) * (same ? 1 : -1);
  }
  return o;
}

// The query point q = v + e (t - v) + s e^2 n, with n the left normal of t - v, s = +1 for
// Side::left and -1 for Side::right, and e infinitesimal: a point just beside the segment
// v -> t near v. Returns the contribution of edge a -> b to the winding number of q, counted
// on the vertical ray upwards from q: +1 for an edge passing above q westwards, -1
// eastwards. Every comparison with q is decided by the first non-zero term of its expansion
// in e, from orientations of input points only; no edge needs to be excluded.
template <Kernel K>
int vertical_ray_crossing(const typename K::Point& v, const typename K::Point& t, Side side,
                          const typename K::Point& a, const typename K::Point& b) {
  const int s = side == Side::left ? 1 : -1;
  // sign(p.x - q.x)
  const auto side_x = [&](const typename K::Point& p) {
    const Sign c = K::compare_x(p, v);
    if (c != Sign::zero) return static_cast<int>(c);
    const Sign dx = K::compare_x(t, v);
    if (dx != Sign::zero) return -static_cast<int>(dx);
    return s * static_cast<int>(K::compare_y(t, v));  // n.x = -(t.y - v.y)
  };
  const int sa = side_x(a);
  const int sb = side_x(b);
  if (sa == sb) return 0;
  const int o = orient_beside<K>(a, b, v, t, side);
  if (sa < 0) return o < 0 ? -1 : 0;  // eastwards: counts when q lies to its right (below)
  return o > 0 ? 1 : 0;               // westwards: counts when q lies to its left (below)
}

}  // namespace mk
