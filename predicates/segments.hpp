// Segment-pair classification and point order on a line, from orient2d and compare_x/y.
// [MK89 §2.1] (intersection of two segments) [MK89 §3.1 step 3]
// Preconditions: segments have distinct endpoints.
#pragma once

#include <algorithm>
#include <vector>

#include "kernel/kernel.hpp"

namespace mk {

// Lexicographic comparison of input points: x first, then y.
template <Kernel K>
Sign compare_xy(const typename K::Point& a, const typename K::Point& b) {
  const Sign sx = K::compare_x(a, b);
  return sx != Sign::zero ? sx : K::compare_y(a, b);
}

// Whether r lies strictly between p and q, given that the three are collinear.
template <Kernel K>
bool is_strictly_between(const typename K::Point& p, const typename K::Point& q,
                         const typename K::Point& r) {
  const Sign a = compare_xy<K>(p, r);
  const Sign b = compare_xy<K>(r, q);
  return a != Sign::zero && a == b;
}

// How two segments ab and cd meet. A proper crossing is a single point interior to both;
// every other contact (touching, collinear overlap) shows as endpoints of one segment lying
// strictly inside the other, which is all the algorithm needs (vertex_on_edge,
// collinear_overlap). Shared endpoints show as nothing.
struct SegmentRelation {
  bool proper_crossing = false;
  bool c_inside_ab = false;
  bool d_inside_ab = false;
  bool a_inside_cd = false;
  bool b_inside_cd = false;
  bool touches() const { return c_inside_ab || d_inside_ab || a_inside_cd || b_inside_cd; }
};

template <Kernel K>
SegmentRelation relate_segments(const typename K::Point& a, const typename K::Point& b,
                                const typename K::Point& c, const typename K::Point& d) {
  SegmentRelation r;
  const Sign oc = K::orient2d(a, b, c);
  const Sign od = K::orient2d(a, b, d);
  if (oc != Sign::zero && oc == od) return r;
  const Sign oa = K::orient2d(c, d, a);
  const Sign ob = K::orient2d(c, d, b);
  if (oa != Sign::zero && oa == ob) return r;
  if (oc != Sign::zero && od != Sign::zero && oa != Sign::zero && ob != Sign::zero) {
    r.proper_crossing = true;
    return r;
  }
  r.c_inside_ab = oc == Sign::zero && is_strictly_between<K>(a, b, c);
  r.d_inside_ab = od == Sign::zero && is_strictly_between<K>(a, b, d);
  r.a_inside_cd = oa == Sign::zero && is_strictly_between<K>(c, d, a);
  r.b_inside_cd = ob == Sign::zero && is_strictly_between<K>(c, d, b);
  return r;
}

// relate_segments for segments given by point ids (equal ids are equal points): segments
// sharing an endpoint take one orientation instead of four.
template <Kernel K>
SegmentRelation relate_segments_by_id(const std::vector<typename K::Point>& pts, int a, int b, int c, int d) {
  const auto shared = [&](int p, int q, int r, bool& q_in, bool& r_in) {
    SegmentRelation rel;
    if (K::orient2d(pts[p], pts[q], pts[r]) != Sign::zero) return rel;
    q_in = is_strictly_between<K>(pts[p], pts[r], pts[q]);
    r_in = is_strictly_between<K>(pts[p], pts[q], pts[r]);
    return rel;
  };
  SegmentRelation rel;
  if (a == c) {
    shared(a, b, d, rel.b_inside_cd, rel.d_inside_ab);
  } else if (a == d) {
    shared(a, b, c, rel.b_inside_cd, rel.c_inside_ab);
  } else if (b == c) {
    shared(b, a, d, rel.a_inside_cd, rel.d_inside_ab);
  } else if (b == d) {
    shared(b, a, c, rel.a_inside_cd, rel.c_inside_ab);
  } else {
    rel = relate_segments<K>(pts[a], pts[b], pts[c], pts[d]);
  }
  return rel;
}

// An edge a0a1 of A against an edge b0b1 of B (point ids), as step 3 takes them: nothing
// for the same segment (a shared edge); crossing() for a proper crossing; otherwise on_a(p)
// for each point p of B strictly inside a0a1 and on_b(p) for each point of A strictly inside
// b0b1 (vertex on edge, collinear overlap).
template <Kernel K, class Crossing, class OnA, class OnB>
void relate_edges_across(const std::vector<typename K::Point>& pts, int a0, int a1, int b0, int b1, Crossing&& crossing,
                         OnA&& on_a, OnB&& on_b) {
  if (std::min(a0, a1) == std::min(b0, b1) && std::max(a0, a1) == std::max(b0, b1)) return;
  const auto rel = relate_segments_by_id<K>(pts, a0, a1, b0, b1);
  if (rel.proper_crossing) {
    crossing();
    return;
  }
  if (rel.c_inside_ab) on_a(b0);
  if (rel.d_inside_ab) on_a(b1);
  if (rel.a_inside_cd) on_b(a0);
  if (rel.b_inside_cd) on_b(a1);
}

}  // namespace mk
