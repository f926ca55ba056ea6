// An independent exact reference for regular results: CGAL's Boolean_set_operations_2 over
// Exact_predicates_exact_constructions_kernel (Epeck), fed the same regions as mkbool.
// [BRIEF §1] (regions of the paper's model) [MK89 §2.2]
// Preconditions: the rings of a region do not cross; a ring visiting a point twice is split
// there into cycles that are simple (checked: CgalRegionError otherwise).
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "tests/oracle/membership.hpp"

namespace mk::oracle {

struct CgalRegionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A regularized region as a CGAL::Polygon_set_2<Epeck>. Made from a Region the way the
// paper's model defines it: FAR is the set of points enclosed by an odd number of rings, so
// it is the symmetric difference of the interiors of the rings' simple cycles (whatever
// their direction, their nesting, or how many parts share an edge), complemented for a
// hole-type polygon or an unbounded result. Rings of fewer than 3 points and cycles of zero
// area enclose nothing and are left out: CGAL's sets are regular.
class CgalSet {
 public:
  CgalSet();
  ~CgalSet();
  CgalSet(const CgalSet&);
  CgalSet& operator=(const CgalSet&);

  static CgalSet of(const Region& r);

  // The regularized operation (difference: clos(A - B), which equals clos(int(A - int B))).
  CgalSet apply(Operation op, const CgalSet& b) const;
  CgalSet complement() const;
  // Whether the regularized symmetric difference of the two sets is empty.
  bool same_as(const CgalSet& other) const;
  // The exact area, empty when the set is unbounded.
  std::optional<Q> area() const;
  // Where p lies, by CGAL's own point location.
  Location locate(const QPoint& p) const;
  // A point strictly inside the set, empty when the set is empty.
  std::optional<QPoint> interior_point() const;
  bool is_empty() const;

 private:
  friend Q area_through_polygons_with_holes(Operation op, const Region& a, const Region& b);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// CGAL 5.5's faults that the reference works around, kept runnable so that a test shows
// them (and says when a CGAL release no longer has them):
// - Epeck's line-line intersection is empty for two crossing lines whose coordinates exceed
//   about 2^340 (its interval approximation overflows and decides the result's type), and
//   Arr_segment_traits_2 then fails an assertion or crashes: CGAL is handed every
//   configuration scaled by a power of two into [1, 2) (differential_test.cpp, Frame).
bool epeck_misses_line_crossing(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d);
// - a Polygon_with_holes_2 whose hole touches its outer boundary at a vertex (valid in OGC)
//   breaks CGAL's precondition (Gps_polygon_validation.h: holes disjoint from the outer
//   boundary; checked only in debug builds), and release builds give wrong areas
//   (public-failure-reports.md: 59 instead of 45): the reference never builds one, it forms
//   every region as a symmetric difference of simple cycles (CgalSet::of). This computes the
//   area the naive way: A's and B's first ring the shell, the others its holes.
Q area_through_polygons_with_holes(Operation op, const Region& a, const Region& b);

// The simple cycles of a ring that may visit a point more than once (a ring touching
// itself), split at each repeated point; written here, not borrowed from core/prepare.hpp.
std::vector<QRing> simple_cycles(const QRing& ring);

}  // namespace mk::oracle
