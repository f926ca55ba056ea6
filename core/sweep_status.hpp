// The status of a plane sweep over segments that do not cross: the segments that meet the
// sweep line, ordered from bottom to top, in a balanced tree with binary search by point.
// [Sh76] (Shamos-Hoey: non-crossing segments keep their order along the sweep, and the
// first crossing shows between two neighbours) [BKOS08 §2.1]
// Preconditions: points are kernel points with ids in lexicographic order (x, then y);
// every segment is given as (lo, hi) with lo < hi and lo.x != hi.x (vertical segments are
// never in the status); the segments present at one time cross each other only to the
// right of the sweep line (the first crossing is caught before the sweep reaches it).
#pragma once

#include <memory_resource>
#include <set>
#include <type_traits>
#include <vector>

#include "kernel/kernel.hpp"

namespace mk {

// What a sweep asks of geometry: a point type and the orientation of three points (a kernel
// has both; so do the frames of snap rounding's sweeps).
template <class K>
concept OrientationPredicates = requires(const typename K::Point& p) {
  { K::orient2d(p, p, p) } -> std::same_as<Sign>;
};

// A segment between two point ids, lo < hi.
struct SweepSegment {
  int lo = -1;
  int hi = -1;
};

namespace detail {

// A segment in the tree, with copies of its end points: comparisons walking down the tree
// then read the nodes they visit and nothing else.
template <class P>
struct SweepEntry {
  int segment;
  int lo_id;
  int hi_id;
  P lo;
  P hi;
};

// Orders segments that meet the sweep line by their height on it. Which line is not needed:
// for two segments that do not cross, the one whose left end lies further right is compared
// with the other's supporting line at that end (and at its right end when the left end lies
// on that line), which is their order wherever both meet the sweep line. Two segments on one
// line compare equal. A point compares with a segment by the side of its line it lies on.
template <OrientationPredicates K>
struct BelowOnSweepLine {
  using is_transparent = void;
  using Entry = SweepEntry<typename K::Point>;
  struct At {
    const typename K::Point* point;
  };

  // Sign of the side of e's line that point q lies on: positive above.
  static Sign side(const Entry& e, const typename K::Point& q) { return K::orient2d(e.lo, e.hi, q); }

  // -1: a below b, +1 above, 0 on one line.
  static int compare(const Entry& a, const Entry& b) {
    if (a.segment == b.segment) return 0;
    if (a.lo_id < b.lo_id) return -compare(b, a);
    // b starts first (or both at one point): a's left end against b's line, then its right end.
    if (a.lo_id != b.lo_id) {
      const Sign at_start = side(b, a.lo);
      if (at_start != Sign::zero) return at_start == Sign::positive ? 1 : -1;
    }
    const Sign at_end = side(b, a.hi);
    return at_end == Sign::zero ? 0 : (at_end == Sign::positive ? 1 : -1);
  }

  bool operator()(const Entry& a, const Entry& b) const { return compare(a, b) < 0; }
  bool operator()(const Entry& a, At q) const { return side(a, *q.point) == Sign::positive; }  // a below q
  bool operator()(At q, const Entry& a) const { return side(a, *q.point) == Sign::negative; }  // q below a
};

}  // namespace detail

// The status: segments in a set whose nodes come from a pool (one sweep allocates them and
// frees them at once), with each segment's position kept so that it leaves without a
// search. With `Multi`, segments on one line (collinear overlaps) may be in together.
template <OrientationPredicates K, bool Multi = false>
class SweepStatus {
 public:
  using Order = detail::BelowOnSweepLine<K>;
  using Entry = typename Order::Entry;
  using Set = std::conditional_t<Multi, std::pmr::multiset<Entry, Order>, std::pmr::set<Entry, Order>>;
  using Iterator = typename Set::const_iterator;

  SweepStatus(const std::vector<typename K::Point>& points, const std::vector<SweepSegment>& segments)
      : points_(points), segments_(segments), set_(&arena_), where_(segments.size()) {}

  // Inserts segment i; the iterator is end() when a segment on the same line is already in.
  Iterator insert(int i) {
    const SweepSegment& s = segments_[static_cast<std::size_t>(i)];
    const Entry e{i, s.lo, s.hi, points_[static_cast<std::size_t>(s.lo)], points_[static_cast<std::size_t>(s.hi)]};
    if constexpr (Multi) {
      const auto it = set_.insert(e);
      where_[static_cast<std::size_t>(i)] = it;
      return it;
    } else {
      auto [it, fresh] = set_.insert(e);
      if (!fresh) return end();
      where_[static_cast<std::size_t>(i)] = it;
      return it;
    }
  }
  // Puts segment j, which continues segment i to the right from i's right end, in i's place
  // (the order is unchanged where no segment crosses the two at their common point).
  Iterator replace(int i, int j) {
    const Iterator it = where_[static_cast<std::size_t>(i)];
    const SweepSegment& s = segments_[static_cast<std::size_t>(j)];
    // The key changes in place: its position stays right by the precondition above.
    Entry& e = const_cast<Entry&>(*it);
    e = Entry{j, s.lo, s.hi, points_[static_cast<std::size_t>(s.lo)], points_[static_cast<std::size_t>(s.hi)]};
    where_[static_cast<std::size_t>(j)] = it;
    return it;
  }
  // Removes segment i (which is in); returns the position after it.
  Iterator erase(int i) { return set_.erase(where_[static_cast<std::size_t>(i)]); }
  Iterator find(int i) const { return where_[static_cast<std::size_t>(i)]; }
  // The first segment not below point q (q on it or below it).
  Iterator first_not_below(const typename K::Point& q) const { return set_.lower_bound(typename Order::At{&q}); }
  Sign side(Iterator it, const typename K::Point& q) const { return Order::side(*it, q); }
  Iterator begin() const { return set_.begin(); }
  Iterator end() const { return set_.end(); }

 private:
  const std::vector<typename K::Point>& points_;
  const std::vector<SweepSegment>& segments_;
  std::pmr::unsynchronized_pool_resource arena_;
  Set set_;
  std::vector<Iterator> where_;
};

}  // namespace mk
