// Winding numbers of a set of edges at points just beside an edge, answered through buckets
// of x-ranks: each query tests only the edges whose x-range contains the query's x.
// [MK89 §4.3] (locating one vertex per ring without a scan of the other polygon)
// Preconditions: point ids follow lexicographic order; x_rank[id] is the rank of the
// point's x among the distinct x values.
#pragma once

#include <algorithm>
#include <span>
#include <vector>

#include "core/arrangement.hpp"
#include "predicates/ray.hpp"

namespace mk {

template <Kernel K>
class WindingLocator {
 public:
  // Edges src -> dst as point ids, viewed, not copied: they must outlive the locator.
  // `queries` is how many queries are expected: when they are few, each scans the edges
  // directly (as cheap as indexing them once).
  WindingLocator(const Arrangement<K>& arr, std::span<const Edge> edges, std::size_t queries)
      : arr_(arr), edges_(edges) {
    if (queries <= kDirectScanQueries) {
      direct_ = true;
      return;
    }
    const int ranks = arr.x_rank.empty() ? 1 : arr.x_rank.back() + 1;
    buckets_ = std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(ranks), edges_.size() / 2 + 1));
    ranks_ = ranks;
    begin_.assign(buckets_ + 1, 0);
    for (const Edge& e : edges_) {
      const auto [lo, hi] = bucket_span(e.src, e.dst);
      for (std::size_t k = lo; k <= hi; ++k) ++begin_[k + 1];
    }
    for (std::size_t k = 1; k < begin_.size(); ++k) begin_[k] += begin_[k - 1];
    items_.resize(begin_.back());
    std::vector<std::size_t> fill(begin_.begin(), begin_.end() - 1);
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      const auto [lo, hi] = bucket_span(edges_[e].src, edges_[e].dst);
      for (std::size_t k = lo; k <= hi; ++k) items_[fill[k]++] = e;
    }
  }

  // Winding number at the point just `side` of v -> t near v (see vertical_ray_crossing).
  int winding(int v, int t, Side side) const {
    int wind = 0;
    for_each_crossing(v, t, side, [&](int c) { wind += c; });
    return wind;
  }

  // Number of edges crossing the ray (their parity counts the cycles around the point).
  int crossings(int v, int t, Side side) const {
    int count = 0;
    for_each_crossing(v, t, side, [&](int c) { count += c != 0; });
    return count;
  }

 private:
  static constexpr std::size_t kDirectScanQueries = 4;

  // Calls f(vertical_ray_crossing(...)) for every edge whose x-range contains v's x.
  template <class F>
  void for_each_crossing(int v, int t, Side side, F&& f) const {
    const int r = arr_.x_rank[v];
    const auto visit = [&](int e) {
      const Edge& edge = edges_[static_cast<std::size_t>(e)];
      const int a = edge.src;
      const int b = edge.dst;
      const int ra = arr_.x_rank[a];
      const int rb = arr_.x_rank[b];
      if (r < std::min(ra, rb) || r > std::max(ra, rb)) return;
      f(vertical_ray_crossing<K>(arr_.points[v], arr_.points[t], side, arr_.points[a], arr_.points[b]));
    };
    if (direct_) {
      for (int e = 0; e < static_cast<int>(edges_.size()); ++e) visit(e);
      return;
    }
    const std::size_t k = bucket(r);
    for (std::size_t i = begin_[k]; i < begin_[k + 1]; ++i) visit(items_[i]);
  }

  std::size_t bucket(int rank) const {
    return static_cast<std::size_t>(static_cast<long long>(rank) * static_cast<long long>(buckets_) / ranks_);
  }
  std::pair<std::size_t, std::size_t> bucket_span(int a, int b) const {
    const int ra = arr_.x_rank[a];
    const int rb = arr_.x_rank[b];
    return {bucket(std::min(ra, rb)), bucket(std::max(ra, rb))};
  }

  const Arrangement<K>& arr_;
  std::span<const Edge> edges_;
  bool direct_ = false;
  std::size_t buckets_ = 1;
  int ranks_ = 1;
  std::vector<std::size_t> begin_;
  std::vector<int> items_;
};

}  // namespace mk
