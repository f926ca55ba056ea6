// Vertices to insert strictly inside edges, collected as (edge, vertex) pairs in any order
// while pairs of edges are examined, then read back edge by edge in increasing edge order.
// They are few next to the edges, so they are kept in one flat list rather than one list
// per edge. [MK89 §3.3] (insertion into the vertex rings)
// Preconditions: group() after the last add() and before the first take(); take() is
// called with increasing edge indices.
#pragma once

#include <algorithm>
#include <climits>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/buckets.hpp"

namespace mk {

class EdgeInsertions {
 public:
  void add(int edge, int vertex) { list_.emplace_back(edge, vertex); }
  // Adds every pair of `other` (collected by another part of a search).
  void append(EdgeInsertions&& other) {
    if (list_.empty()) {
      list_ = std::move(other.list_);
    } else {
      list_.insert(list_.end(), other.list_.begin(), other.list_.end());
    }
  }
  bool empty() const { return list_.empty(); }
  std::size_t size() const { return list_.size(); }

  // Orders the pairs by edge (every edge below num_edges), each edge's in the order they
  // were added: a counting sort when they are many, linear where a comparison sort is not
  // (the winding arrangement of many rings inserts hundreds of thousands of crossings, a
  // grid of squares as many touching vertices); a stable comparison sort, the same order,
  // when they are few next to the edges (the counting sort's array would cost more).
  void group(int num_edges) {
    next_ = 0;
    if (list_.size() < static_cast<std::size_t>(num_edges) / 16) {
      std::stable_sort(list_.begin(), list_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      return;
    }
    const Buckets b = bucket_by(list_.size(), static_cast<std::size_t>(num_edges), [&](std::size_t i) { return list_[i].first; });
    std::vector<std::pair<int, int>> by_edge(list_.size());
    for (std::size_t k = 0; k < b.order.size(); ++k) by_edge[k] = list_[static_cast<std::size_t>(b.order[k])];
    list_ = std::move(by_edge);
  }

  // The smallest edge not taken yet that has insertions, or INT_MAX.
  int next_edge() const { return next_ < list_.size() ? list_[next_].first : INT_MAX; }

  // Replaces `out` by the vertices inserted into `edge`, in no particular order and possibly
  // repeated; false when there are none. Edges below `edge` not taken are passed over.
  bool take(int edge, std::vector<int>& out) {
    out.clear();
    while (next_ < list_.size() && list_[next_].first < edge) ++next_;
    for (; next_ < list_.size() && list_[next_].first == edge; ++next_) out.push_back(list_[next_].second);
    return !out.empty();
  }

 private:
  std::vector<std::pair<int, int>> list_;
  std::size_t next_ = 0;
};

}  // namespace mk
