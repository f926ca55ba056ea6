// The parts of a non-regular Boolean result in the order every text writer gives them in a
// geometry collection: its polygons (one member), then each dangling edge, then each
// isolated point. [OGC06-103 §6.1.11] (GeometryCollection)
// Preconditions: none.
#pragma once

#include "core/output.hpp"

namespace mk::io_detail {

// Calls separate() between members, polygons(all polygons) once if there are any,
// edge(p, q) per dangling edge and point(p) per isolated point.
template <class Separate, class Polygons, class EdgeMember, class PointMember>
void for_each_member(const Output& output, Separate&& separate, Polygons&& polygons, EdgeMember&& edge,
                     PointMember&& point) {
  bool first = true;
  const auto next = [&] {
    if (!first) separate();
    first = false;
  };
  if (!output.polygons.empty()) {
    next();
    polygons(output.polygons);
  }
  for (const auto& [a, b] : output.dangling_edges) {
    next();
    edge(a, b);
  }
  for (const Point& p : output.isolated_points) {
    next();
    point(p);
  }
}

}  // namespace mk::io_detail
