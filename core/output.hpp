// A kernel-independent view of a Boolean result, for writers and users: the irreducible
// result polygons with their types [MK89 §3.1 step 6] and the same region assembled into
// OGC polygons-with-holes [MK89 §2.2, inclusion forest].
// Preconditions: produced by mk::boolean_op / mk::to_output; coordinates rounded to nearest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/polygon.hpp"

namespace mk {

// One irreducible result polygon: a cycle of 3+ vertices, a two-sided segment (2 vertices)
// or a one-sided point (1 vertex). `exact` holds "p/q" strings per coordinate (x then y)
// for exact kernels, and is empty otherwise.
struct OutputIrreducible {
  std::vector<Point> vertices;
  std::vector<std::string> exact;  // 2 * vertices.size() strings, or empty
  PolygonType type = PolygonType::island;
};

struct Output {
  std::vector<OutputIrreducible> irreducible;
  // The regular (area) part as OGC polygons with holes; empty when unbounded.
  MultiPolygon polygons;
  // Non-regular parts: dangling edges (two-sided) and isolated points (one-sided).
  std::vector<std::pair<Point, Point>> dangling_edges;
  std::vector<Point> isolated_points;
  // True when the result region is unbounded (its outermost cycles are hole-like): it
  // cannot be written as WKT or GeoJSON, only in the native format.
  bool unbounded = false;
  // Exact kernels only: whether the rounded coordinates still form a valid output (no two
  // edges cross, no ring collapses), checked exactly. Empty for inexact kernels.
  std::optional<bool> rounded_valid;
};

}  // namespace mk
