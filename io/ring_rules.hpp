// Ring rules shared by the readers and writers: OGC closed-ring validation, removal of
// repeated vertices, and the exact orientation of a ring for the writers' right-hand rule.
// [OGC06-103 §6.1.7] [RFC7946 §3.1.6]
// Preconditions: coordinates are finite (the readers reject NaN and infinity first).
#pragma once

#include <cstddef>
#include <string>

#include "core/polygon.hpp"

namespace mk::io_detail {

// What is wrong with a ring written in closed form (first vertex repeated at the end), as
// WKT and GeoJSON require.
enum class OgcRingProblem { none, too_few_coordinates, not_closed, too_few_distinct_points };

OgcRingProblem check_ogc_ring(const Ring& closed);

// A sentence describing the problem, with the counts or the offending vertices.
std::string describe_ogc_ring_problem(const Ring& closed, OgcRingProblem problem);

// Removes consecutive duplicate vertices (including a duplicate across the wrap-around), so
// that the ring is in the paper's form: no closing vertex, no zero-length edge.
void remove_repeated_vertices(Ring& ring);

// The exact sign of the ring's signed area: +1 counterclockwise, -1 clockwise, 0 for a
// ring of zero area. One exact (adaptive) orientation test at the lexicographically lowest
// vertex decides it, GMP rationals the whole area only when that test is degenerate, so a
// million-vertex ring costs one pass of double comparisons.
int ring_orientation(const Ring& ring);

// Calls visit(point, is_first) for the ring in closed form (the first vertex repeated at the
// end), reversed if needed so that it runs counterclockwise or clockwise as asked. A ring
// of zero area is visited as given.
template <class Visit>
void visit_closed_ring(const Ring& ring, bool counterclockwise, Visit&& visit) {
  if (ring.empty()) return;
  const int orientation = ring_orientation(ring);
  const bool reverse = orientation != 0 && (orientation > 0) != counterclockwise;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i <= n; ++i) {
    const std::size_t k = i % n;
    visit(ring[reverse ? (n - k) % n : k], i == 0);
  }
}

}  // namespace mk::io_detail
