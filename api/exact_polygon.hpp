// Polygons with exact rational coordinates: the input form that takes an exact result back
// (exact in, exact out), and its conversions to and from doubles. [MK89 §2.2] [BRIEF §6a]
// Preconditions: none; a coordinate whose nearest double is infinite is refused by
// validate_exact_coordinates.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"
#include "core/error.hpp"
#include "core/polygon.hpp"

namespace mk {

using ExactRing = BasicRing<RationalPoint>;
using ExactPolygon = BasicPolygon<RationalPoint>;

// The polygon with every point mapped by f (same type, same rings), e.g. to another
// coordinate type.
template <class P, class F>
auto map_points(const BasicPolygon<P>& p, F&& f) {
  BasicPolygon<std::remove_cvref_t<decltype(f(p.rings.front().front()))>> out;
  out.type = p.type;
  for (const auto& ring : p.rings) {
    auto& r = out.rings.emplace_back();
    r.reserve(ring.size());
    for (const auto& q : ring) r.push_back(f(q));
  }
  return out;
}

// The polygon as doubles when every coordinate is exactly a double, else nullopt.
inline std::optional<Polygon> as_double_polygon(const ExactPolygon& p) {
  Polygon out;
  out.type = p.type;
  for (const auto& ring : p.rings) {
    auto& r = out.rings.emplace_back();
    for (const auto& q : ring) {
      const double x = nearest_double(q.x), y = nearest_double(q.y);
      if (!std::isfinite(x) || !std::isfinite(y) || cmp(mpq_class(x), q.x) != 0 || cmp(mpq_class(y), q.y) != 0) {
        return std::nullopt;
      }
      r.push_back({x, y});
    }
  }
  return out;
}

// Each coordinate rounded to its nearest double (for messages and pictures).
inline Polygon nearest_polygon(const ExactPolygon& p) {
  return map_points(p, [](const RationalPoint& q) { return Point{nearest_double(q.x), nearest_double(q.y)}; });
}

// Doubles taken exactly.
inline ExactPolygon exact_polygon(const Polygon& p) {
  return map_points(p, [](const Point& q) { return RationalPoint{mpq_class(q.x), mpq_class(q.y)}; });
}

// Throws InvalidInput when a coordinate of `p` (named `name` in the message) lies beyond the
// doubles (its nearest double is infinite): results must be writable as doubles.
inline void validate_exact_coordinates(const ExactPolygon& p, const std::string& name) {
  for (std::size_t r = 0; r < p.rings.size(); ++r) {
    for (std::size_t v = 0; v < p.rings[r].size(); ++v) {
      const auto& q = p.rings[r][v];
      if (!std::isfinite(nearest_double(q.x)) || !std::isfinite(nearest_double(q.y))) {
        throw InvalidInput((name.empty() ? std::string() : "polygon " + name + ", ") + "ring " + std::to_string(r) + ", vertex " + std::to_string(v) +
                           ": coordinate beyond the range of doubles (results are written as doubles)");
      }
    }
  }
}

}  // namespace mk
