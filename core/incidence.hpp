// Incidence of edge fragments at vertices (each fragment seen from its two ends, grouped by
// vertex) and counts of fragments that coincide as sets; used by steps 4 and 5. Not to be
// confused with the locating ray of predicates/ray.hpp.
// [MK89 §4.3] (classification at boundary points) [MK89 §3.3] (EF: matching fragments)
// Preconditions: step 3 done.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/arrangement.hpp"
#include "predicates/directions.hpp"

namespace mk {

// A fragment seen from one of its endpoints: the fragment's index, +1 when it leaves the
// vertex and -1 when it arrives, and the direction away from the vertex (given by the
// original edge's input points). Stored as one int, 2 fragment + 1 when it arrives; the
// direction is looked up only when asked for.
class FragmentEnd {
 public:
  FragmentEnd(const PreparedPolygon& poly, int code) : poly_(&poly), code_(code) {}
  int fragment() const { return code_ >> 1; }
  int sign() const { return (code_ & 1) != 0 ? -1 : 1; }
  Direction dir() const {
    const Edge& e = poly_->edges[poly_->fragments[fragment()].edge];
    return (code_ & 1) != 0 ? Direction{e.dst, e.src} : Direction{e.src, e.dst};
  }

 private:
  const PreparedPolygon* poly_;
  int code_;
};

// The ends of one polygon's fragments, grouped by vertex, each stored as its code: the
// table costs 4 bytes per vertex and 8 per fragment, and is built without a second
// per-vertex array.
// A bit per vertex says whether the polygon reaches it at all: most queries are about the
// other polygon's vertices, which it does not reach, and the bits (1/32 of the groups'
// size) answer them from cache.
// The polygon must outlive the table and keep its fragments and edges in place.
class FragmentEndTable {
 public:
  FragmentEndTable() = default;
  FragmentEndTable(const PreparedPolygon& poly, int num_vertices) : poly_(&poly) {
    // begin_[v] first counts v's fragment ends, then holds the end of v's group, and is moved down
    // to its start as the group is filled from the back.
    begin_.assign(static_cast<std::size_t>(num_vertices) + 1, 0);
    for (const auto& f : poly.fragments) {
      ++begin_[f.from];
      ++begin_[f.to];
    }
    reached_.assign(static_cast<std::size_t>(num_vertices) / 64 + 1, 0);
    int total = 0;
    for (std::size_t v = 0; v < begin_.size(); ++v) {
      reached_[v / 64] |= static_cast<std::uint64_t>(begin_[v] > 0) << (v % 64);
      total += begin_[v];
      begin_[v] = total;
    }
    codes_.resize(static_cast<std::size_t>(total));
    for (int i = static_cast<int>(poly.fragments.size()) - 1; i >= 0; --i) {
      const auto& f = poly.fragments[i];
      codes_[--begin_[f.to]] = 2 * i + 1;
      codes_[--begin_[f.from]] = 2 * i;
    }
  }

  class Iterator {
   public:
    Iterator(const PreparedPolygon* poly, const int* code) : poly_(poly), code_(code) {}
    FragmentEnd operator*() const { return {*poly_, *code_}; }
    Iterator& operator++() {
      ++code_;
      return *this;
    }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.code_ == b.code_; }

   private:
    const PreparedPolygon* poly_;
    const int* code_;
  };
  struct Span {
    Iterator b;
    Iterator e;
    Iterator begin() const { return b; }
    Iterator end() const { return e; }
    bool empty() const { return b == e; }
  };
  bool reaches(int v) const { return (reached_[static_cast<std::size_t>(v) / 64] >> (v % 64)) & 1; }
  int count(int v) const { return begin_[v + 1] - begin_[v]; }
  Span at(int v) const {
    return {{poly_, codes_.data() + begin_[v]}, {poly_, codes_.data() + begin_[v + 1]}};
  }

 private:
  const PreparedPolygon* poly_ = nullptr;
  std::vector<int> begin_;
  std::vector<int> codes_;
  std::vector<std::uint64_t> reached_;  // bit v: v has fragment ends
};

// Fragments of polygon x lying on u -> w: (same direction, opposite direction), found among
// x's fragment ends at u, which are few.
inline std::pair<int, int> fragments_along(const PreparedPolygon& x, const FragmentEndTable& x_ends, int u, int w) {
  int same = 0;
  int opposite = 0;
  if (!x_ends.reaches(u)) return {0, 0};
  for (const FragmentEnd& end : x_ends.at(u)) {
    const Fragment& f = x.fragments[end.fragment()];
    if (end.sign() > 0 && f.to == w) ++same;
    if (end.sign() < 0 && f.from == w) ++opposite;
  }
  return {same, opposite};
}

// Both polygons' fragment ends by vertex: what steps 4 and 5 read about the arrangement
// besides the fragments themselves (index 0 for A, 1 for B).
struct Incidence {
  std::array<FragmentEndTable, 2> ends;
};

}  // namespace mk
