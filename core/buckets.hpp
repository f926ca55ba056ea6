// Items grouped by a small integer key in linear time (a stable counting sort), the
// grouping several phases need: edges by point, insertions by edge, visits by vertex.
// [Cormen et al., Introduction to Algorithms, §8.2] (counting sort)
// Preconditions: every key(i) lies in [0, num_keys).
#pragma once

#include <cstddef>
#include <vector>

namespace mk {

// The items 0 .. count-1 by key: those with key k are order[begin[k] .. begin[k + 1]), in
// increasing index.
struct Buckets {
  std::vector<int> begin;  // num_keys + 1 offsets
  std::vector<int> order;  // item indices
};

template <class Key>
Buckets bucket_by(std::size_t count, std::size_t num_keys, Key&& key) {
  Buckets b;
  b.begin.assign(num_keys + 1, 0);
  for (std::size_t i = 0; i < count; ++i) ++b.begin[static_cast<std::size_t>(key(i)) + 1];
  for (std::size_t k = 1; k < b.begin.size(); ++k) b.begin[k] += b.begin[k - 1];
  b.order.resize(count);
  std::vector<int> fill(b.begin.begin(), b.begin.end() - 1);
  for (std::size_t i = 0; i < count; ++i) b.order[static_cast<std::size_t>(fill[static_cast<std::size_t>(key(i))]++)] = static_cast<int>(i);
  return b;
}

}  // namespace mk
