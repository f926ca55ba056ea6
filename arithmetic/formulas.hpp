// The predicate formulas, each written once as a template over the number type.
// [MK89 §2.1] (east/west of a directed line) [Sh97]
// Preconditions: T is exact (mpq_class) or the caller accepts rounding (double).
#pragma once

namespace mk::formula {

// (b - a) x (c - a): positive when c lies west (left) of the directed line a -> b.
template <class T>
T orient2d(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// (q1 - p1) x (q2 - p2).
template <class T>
T cross_of_differences(const T& p1x, const T& p1y, const T& q1x, const T& q1y, const T& p2x,
                       const T& p2y, const T& q2x, const T& q2y) {
  return (q1x - p1x) * (q2y - p2y) - (q1y - p1y) * (q2x - p2x);
}

// The crossing of lines a0a1 and b0b1 as a0 + t (a1 - a0), with
// t = ((b0 - a0) x (b1 - b0)) / ((a1 - a0) x (b1 - b0)). Writes x and y.
template <class T>
void line_crossing(const T& a0x, const T& a0y, const T& a1x, const T& a1y, const T& b0x,
                   const T& b0y, const T& b1x, const T& b1y, T& x, T& y) {
  const T dbx = b1x - b0x;
  const T dby = b1y - b0y;
  const T num = (b0x - a0x) * dby - (b0y - a0y) * dbx;
  const T den = (a1x - a0x) * dby - (a1y - a0y) * dbx;
  const T t = num / den;
  x = a0x + t * (a1x - a0x);
  y = a0y + t * (a1y - a0y);
}

}  // namespace mk::formula
