// Canonical form of a result for exact comparison: each irreducible polygon rotated to start
// at its smallest vertex, with its type, and the list sorted. Exact kernels are compared by
// their exact rational vertices; inexact ones by their rounded doubles.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "named_cases.hpp"
#include "oracle.hpp"

namespace mk::test {

using Canonical = std::vector<std::pair<PolygonType, std::vector<std::pair<Q, Q>>>>;

inline Canonical canonical(Canonical cycles) {
  for (auto& [type, v] : cycles) std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  std::sort(cycles.begin(), cycles.end());
  return cycles;
}

inline Canonical canonical(const std::vector<ExpectedCycle>& e) {
  Canonical c;
  for (const auto& cyc : e) {
    auto& [type, v] = c.emplace_back();
    type = cyc.type;
    for (const auto& p : cyc.vertices) v.push_back({Q(p.x), Q(p.y)});
  }
  return canonical(c);
}

template <class K>
Canonical canonical(const BooleanResult<K>& r) {
  Canonical c;
  for (const auto& cyc : r.cycles) {
    auto& [type, v] = c.emplace_back();
    type = cyc.type;
    for (const int id : cyc.vertices) {
      if constexpr (K::is_exact) {
        const auto e = K::exact_coordinates(r.vertex(id));
        v.push_back({Q(e[0]), Q(e[1])});
      } else {
        const Point p = K::approx(r.vertex(id));
        v.push_back({Q(p.x), Q(p.y)});
      }
    }
  }
  return canonical(c);
}

inline std::string show(const Canonical& c) {
  std::string s;
  for (const auto& [type, v] : c) {
    s += type == PolygonType::island ? "  island" : "  hole";
    for (const auto& [x, y] : v) s += " (" + x.get_str() + " " + y.get_str() + ")";
    s += "\n";
  }
  return s.empty() ? "  (empty)\n" : s;
}

}  // namespace mk::test
