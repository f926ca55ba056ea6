// Canonical form of a Boolean result for exact comparison: each irreducible result polygon
// from its least rotation (a cycle has no distinguished start, but its direction is part of
// the result), with its type, and the polygons sorted.
// [MK89 §3.1 step 6] (irreducible result polygons and their types)
// Preconditions: Less is a strict weak order on the vertex type V (coordinates, exact or
// rounded: the caller chooses what "equal" means).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "core/polygon.hpp"

namespace mk {

template <class V>
using CanonicalCycle = std::pair<PolygonType, std::vector<V>>;

// The rotation of cycle vs that is least in lexicographic order. Only rotations starting at
// a least vertex compete (usually one: cycles have distinct vertices, though rounded ones
// may repeat).
template <class V, class Less = std::less<V>>
std::vector<V> least_rotation(const std::vector<V>& vs, Less less = {}) {
  const std::size_t n = vs.size();
  const auto at = [&](std::size_t start, std::size_t i) -> const V& { return vs[(start + i) % n]; };
  std::size_t best = 0;
  for (std::size_t s = 1; s < n; ++s) {
    if (less(vs[s], vs[best])) best = s;
  }
  for (std::size_t s = best + 1; s < n; ++s) {
    if (less(vs[best], vs[s]) || less(vs[s], vs[best])) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (less(at(s, i), at(best, i))) {
        best = s;
        break;
      }
      if (less(at(best, i), at(s, i))) break;
    }
  }
  std::vector<V> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(at(best, i));
  return out;
}

// Every cycle from its least rotation, the cycles sorted by type, length, then vertices.
template <class V, class Less = std::less<V>>
std::vector<CanonicalCycle<V>> canonical(std::vector<CanonicalCycle<V>> cycles, Less less = {}) {
  for (auto& [type, vs] : cycles) vs = least_rotation(vs, less);
  std::sort(cycles.begin(), cycles.end(), [&](const CanonicalCycle<V>& a, const CanonicalCycle<V>& b) {
    if (a.first != b.first) return a.first < b.first;
    if (a.second.size() != b.second.size()) return a.second.size() < b.second.size();
    return std::lexicographical_compare(a.second.begin(), a.second.end(), b.second.begin(), b.second.end(), less);
  });
  return cycles;
}

}  // namespace mk
