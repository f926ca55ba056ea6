// Canonical form of a result for exact comparison (core/canonical.hpp) over exact rational
// vertices: exact kernels by their exact coordinates, inexact ones by their rounded doubles.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "core/canonical.hpp"
#include "named_cases.hpp"
#include "oracle.hpp"

namespace mk::test {

using Canonical = std::vector<CanonicalCycle<std::pair<Q, Q>>>;

inline Canonical canonical(Canonical cycles) { return mk::canonical(std::move(cycles)); }

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
